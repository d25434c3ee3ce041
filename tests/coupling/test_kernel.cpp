// The particle <-> lattice kernel (coupling/kernel.hpp): conservation of deposited volume and
// force to round-off (walls, solids, periodic seams, parcels wider than a cell, kernels wider than
// the box), the solid-fraction noise of a random bed against its Poisson variance, exact
// interpolation of constant and linear fields and of a linear pressure's gradient, the width the
// kernel claims, continuity of a moving particle's footprint, the clipping report, and bitwise
// equality at 1 and 2 threads.
#include <omp.h>

#include <catch2/catch.hpp>

#include "coupling/kernel.hpp"
#include "lbm/lbm_solver.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace lbdem;
using namespace lbdem::coupling;
using lbm::Grid;
using lbm::LatticeFrame;

namespace {

// An SI frame away from the origin, so that the lattice <-> SI mapping is exercised.
const LatticeFrame kFrame{Vec3(1e-3, -2e-3, 5e-4), 2e-4};
const double kDx = kFrame.dx;

double sphere_volume(double r) {
  return 4.0 / 3.0 * kPi * r * r * r;
}

// A solid block in compact order: cells lo <= (x, y, z) < hi.
std::vector<std::uint8_t> block_mask(const Grid& g, std::array<int, 3> lo, std::array<int, 3> hi) {
  std::vector<std::uint8_t> m(std::size_t(g.cells()), 0);
  for (int z = lo[2]; z < hi[2]; ++z)
    for (int y = lo[1]; y < hi[1]; ++y)
      for (int x = lo[0]; x < hi[0]; ++x) m[std::size_t(g.compact_index(x, y, z))] = 1;
  return m;
}

// Positions [m] that probe every special place of a box periodic in x and y with walls in z
// (lattice coordinates: faces at -1/2 and n - 1/2): on and beyond the wall faces, on and across
// the periodic seams (also far outside, wrapping), inside a solid block, and at random.
std::vector<Vec3> awkward_positions(const Grid& g, std::array<int, 3> block_centre) {
  const double nx = g.nx(), ny = g.ny(), nz = g.nz();
  std::vector<Vec3> lu = {
      {3.3, 2.1, -0.5},
      {7.2, 4.4, -0.49},
      {9.9, 6.0, 0.1},
      {1.0, 1.0, nz - 0.5},
      {5.5, 3.3, nz - 0.3},
      {2.2, 5.1, nz + 0.3},
      {4.4, 0.5, -2.0},
      {-0.5, 3.0, 5.0},
      {-0.2, -0.4, 6.1},
      {nx - 0.3, ny - 0.5, 3.3},
      {nx + 0.3, 2.0, 7.7},
      {-3.1, ny + 5.2, 2.5},
      {nx - 0.5, -0.5, -0.5},
      {double(block_centre[0]), double(block_centre[1]), double(block_centre[2])},
  };
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int p = 0; p < 200; ++p)
    lu.emplace_back(nx * u(rng) - 0.5, ny * u(rng) - 0.5, nz * u(rng) - 0.5);
  std::vector<Vec3> x;
  for (const Vec3& l : lu) x.push_back(kFrame.to_si(l));
  return x;
}

}  // namespace

TEST_CASE("Kernel: deposited volume equals the particle volume to round-off anywhere",
          "[coupling]") {
  // x periodic (20 cells), y periodic and narrower than the wide kernel (8 cells, so it wraps
  // more than twice), walls in z; a solid block resting on the lower wall. Then the axes swapped
  // (walls in x and y, z periodic), since the passes along x, y and z are separate code.
  for (const Grid& g :
       {Grid(20, 8, 12, {true, true, false}), Grid(14, 12, 10, {false, false, true})}) {
    const auto solid = block_mask(g, {8, 2, 0}, {12, 5, 4});
    const std::vector<Vec3> x = awkward_positions(g, {10, 3, 2});
    struct Case {
      double diameter, width;
    };
    // Sub-cell particles at the default width (sigma = dx), and parcels of 3 dx at sigma = 2 d.
    for (const Case& k :
         {Case{0.5 * kDx, default_kernel_width(kDx, 0.5 * kDx)}, Case{3 * kDx, 6 * kDx}}) {
      ParticleKernel kernel(g, kFrame, k.width, solid);
      kernel.locate(x);
      REQUIRE(kernel.unmapped_count() == 0);
      std::vector<double> vol(x.size());
      double total = 0;
      for (std::size_t p = 0; p < x.size(); ++p) {
        vol[p] = sphere_volume(0.5 * k.diameter * (0.8 + 0.2 * std::sin(double(p))));
        total += vol[p];
      }
      std::vector<double> phi;
      kernel.deposit(vol, phi);
      double deposited = 0, in_solid = 0;
      for (std::size_t c = 0; c < phi.size(); ++c) {
        deposited += phi[c] * kernel.cell_volume();
        if (solid[c]) in_solid += std::abs(phi[c]);
      }
      INFO("width " << k.width / kDx << " dx, taps " << 2 * kernel.half_taps() + 1 << ", deposited "
                    << deposited << " of " << total);
      // Every cell value passes 3 (2H + 1) <= 111 multiply-adds and the total sums 1920 cells: the
      // accumulated relative round-off stays near 1e-15; a kernel that lost its truncated tails
      // or a wall's share would be off by 1e-3 or more.
      CHECK(std::abs(deposited - total) < 1e-13 * total);
      CHECK(in_solid == 0.0);  // solid cells receive nothing, exactly

      // gas_fraction is 1 - phi on the same kernel, here with radii / 4 so that nothing is clipped
      // (the parcels above hold more volume than the box).
      std::vector<double> radii(x.size()), eps;
      for (std::size_t p = 0; p < x.size(); ++p)
        radii[p] = 0.25 * std::cbrt(vol[p] * 3 / (4 * kPi));
      const PorosityReport r = kernel.gas_fraction(radii, kDefaultEpsMin, eps);
      CHECK(r.clipped == 0);
      double eps_deficit = 0;
      for (std::size_t c = 0; c < eps.size(); ++c)
        if (!solid[c]) eps_deficit += (1 - eps[c]) * kernel.cell_volume();
      // 1 - (1 - phi) loses up to 1.1e-16 per cell against phi ~ 0.01-0.1: 1e-12 of the total.
      CHECK(std::abs(eps_deficit - total / 64) < 1e-12 * total);
    }
  }
}

TEST_CASE("Kernel: a particle buried deeper than the kernel reach is reported, not deposited",
          "[coupling]") {
  const Grid g(16, 16, 16);
  const auto solid = block_mask(g, {2, 2, 2}, {14, 14, 14});
  ParticleKernel kernel(g, kFrame, kDx, solid);  // reach H + 1 = 3 cells
  const std::vector<Vec3> x = {kFrame.to_si(Vec3(0, 0, 0)), kFrame.to_si(Vec3(8, 8, 8)),
                               kFrame.to_si(Vec3(7.5, 8, 8.2))};
  kernel.locate(x);
  CHECK(kernel.unmapped_count() == 2);
  CHECK(kernel.first_unmapped() == 1);
  std::vector<double> q = {1.0, 1.0, 1.0}, dep, at;
  kernel.deposit(q, dep);
  double sum = 0;
  for (double d : dep) sum += d * kernel.cell_volume();
  CHECK(std::abs(sum - 1.0) < 1e-14);  // only the mapped particle, to round-off
  kernel.interpolate(std::vector<double>(std::size_t(g.cells()), 2.0), at);
  CHECK(at[1] == 0.0);
  CHECK(std::abs(at[0] - 2.0) < 1e-14);
}

TEST_CASE("Kernel: the solver's geometry becomes the solid mask", "[coupling]") {
  lbm::LbmSettings s;
  s.nx = 6;
  s.ny = 5;
  s.nz = 4;
  s.faces[4].kind = s.faces[5].kind = lbm::FaceKind::wall;
  lbm::LbmSolver lbm(s);
  const int body = lbm.add_body("block");
  lbm.set_cell(2, 3, 1, body);
  lbm.set_cell(5, 0, 3, body);
  const std::vector<std::uint8_t> mask = ParticleKernel::solid_mask(lbm.flags());
  REQUIRE(mask.size() == std::size_t(lbm.grid().cells()));
  std::size_t solid = 0;
  for (std::uint8_t m : mask) solid += m;
  CHECK(solid == 2);  // interior cells only: the wall faces lie in the ghost layers
  CHECK(mask[std::size_t(lbm.grid().compact_index(2, 3, 1))] == 1);
  CHECK(mask[std::size_t(lbm.grid().compact_index(5, 0, 3))] == 1);
}

TEST_CASE("Kernel: force deposition conserves momentum to round-off", "[coupling]") {
  const Grid g(20, 8, 12, {true, true, false});
  const auto solid = block_mask(g, {8, 2, 0}, {12, 5, 4});
  const std::vector<Vec3> x = awkward_positions(g, {10, 3, 2});
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n01;
  std::vector<Vec3> force(x.size());
  Vec3 total = Vec3::Zero();
  double scale = 0;
  for (Vec3& f : force) {
    f = 1e-6 * Vec3(n01(rng), n01(rng), n01(rng));  // [N]
    total += f;
    scale += f.norm();
  }
  for (double width : {kDx, 2.5 * kDx, 6 * kDx}) {
    ParticleKernel kernel(g, kFrame, width, solid);
    kernel.locate(x);
    std::vector<Vec3> density;  // [N/m^3]
    kernel.deposit(force, density);
    Vec3 sum = Vec3::Zero();
    double in_solid = 0;
    for (std::size_t c = 0; c < density.size(); ++c) {
      sum += density[c] * kernel.cell_volume();
      if (solid[c]) in_solid += density[c].norm();
    }
    INFO("width " << width / kDx << " dx: sum " << sum.transpose() << " vs " << total.transpose());
    // Relative to sum |F|: forces of both signs cancel in the total, so its own size is no scale
    // for the round-off; 1e-13 as for the volume.
    CHECK((sum - total).norm() < 1e-13 * scale);
    CHECK(in_solid == 0.0);
  }
}

TEST_CASE("Kernel: a uniform random bed has the solid fraction and Poisson noise derived",
          "[coupling]") {
  // N equal spheres at independent uniform positions in a periodic box (overlaps allowed: an
  // ideal-gas arrangement; the exclusion of a real packing only lowers the variance, by its
  // structure factor S(0) < 1). With K_p(c) the kernel weight of cell c:
  //   E phi(c) = N V_p / V_box  (sum_c K_p = 1 and the distribution is shift-invariant),
  //   var phi(c) = N (V_p / dx^3)^2 (E K^2 - 1 / N_c^2),  E K^2 = E_f [sum_c K^2] / N_c.
  // Away from walls K is the product over axes of k(i) = (1 - f) g(i) + f g(i - 1) (trilinear
  // then filter), so sum_c K^2 is the product of sum_i k(i)^2, whose mean over f uniform in
  // [0, 1) is (2 Q + C) / 3 with Q = sum g(i)^2, C = sum g(i) g(i - 1).
  const int n = 32;
  const Grid g(n, n, n);
  const double d = kDx, vp = sphere_volume(0.5 * d), target = 0.3;
  const double ncell = double(g.cells());
  const auto np = std::size_t(std::lround(target * ncell * kDx * kDx * kDx / vp));
  const double phi0 = np * vp / (ncell * kDx * kDx * kDx);
  ParticleKernel kernel(g, kFrame, default_kernel_width(kDx, d), {});  // sigma = 2 dx
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, n);
  std::vector<Vec3> x(np);
  for (Vec3& p : x) p = kFrame.to_si(Vec3(u(rng), u(rng), u(rng)) - Vec3::Constant(0.5));
  kernel.locate(x);
  std::vector<double> eps;
  const PorosityReport r =
      kernel.gas_fraction(std::vector<double>(np, 0.5 * d), kDefaultEpsMin, eps);

  const auto& t = kernel.taps();
  const int h = kernel.half_taps();
  auto tap = [&](int k) { return std::abs(k) <= h ? t[std::size_t(std::abs(k))] : 0.0; };
  double q = 0, cc = 0;
  for (int k = -h; k <= h + 1; ++k) q += tap(k) * tap(k), cc += tap(k) * tap(k - 1);
  const double s = (2 * q + cc) / 3;
  const double sd = std::sqrt(np * std::pow(vp / (kDx * kDx * kDx), 2) *
                              (s * s * s / ncell - 1 / (ncell * ncell)));
  double mean = 0, var = 0, worst = 0;
  for (double e : eps) mean += 1 - e;
  mean /= ncell;
  for (double e : eps) {
    var += std::pow(1 - e - phi0, 2);
    worst = std::max(worst, std::abs(1 - e - phi0));
  }
  const double sample_sd = std::sqrt(var / ncell);
  INFO("N " << np << " phi0 " << phi0 << " mean " << mean << " sd " << sample_sd << " predicted "
            << sd << " worst " << worst / sd << " sd");
  CHECK(r.clipped == 0);
  CHECK(std::abs(mean - phi0) < 1e-13);  // conservation: the mean is exact
  // Each cell sums hundreds of kernels, so phi(c) is near Gaussian; 6 sd over 32768 cells
  // is exceeded with probability < 32768 x 2e-9 (union bound).
  CHECK(worst < 6 * sd);
  // The cells are correlated over the kernel (about (2 sqrt(pi) sigma)^3 = 360 cells), so the
  // sample variance has about 90 independent samples: sd of the sample sd ~ 1/sqrt(180) = 7.5 %;
  // 25 % is 3.3 of those.
  CHECK(sample_sd > 0.75 * sd);
  CHECK(sample_sd < 1.25 * sd);
}

TEST_CASE("Kernel: the variance per axis is sigma^2 averaged over the position in the cell",
          "[coupling]") {
  // Second moment of K_p about x_p along x: var(g) + f (1 - f), f the offset from the lower cell
  // centre (trilinear step); its mean over f uniform in [0, 1) is var(g) + 1/6, which the
  // constructor sets to (sigma / dx)^2. So m2 - f (1 - f) must be (sigma / dx)^2 - 1/6 at every f.
  const int n = 40;
  const Grid g(n, n, n);
  for (double width : {kDx, 2.7 * kDx}) {
    ParticleKernel kernel(g, kFrame, width, {});
    for (double f : {0.0, 0.25, 0.5, 0.75}) {
      const double xp = 20 + f;
      kernel.locate(std::vector<Vec3>{kFrame.to_si(Vec3(xp, 20, 20))});
      std::vector<double> dep;
      kernel.deposit(std::vector<double>{1.0}, dep);
      double m2 = 0;
      for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x)
            m2 += (x - xp) * (x - xp) * dep[std::size_t(g.compact_index(x, y, z))] *
                  kernel.cell_volume();
      // The filter's variance alone, the same at every f: to round-off (bisection to 1e-15 R).
      CHECK(std::abs(m2 - f * (1 - f) - ((width / kDx) * (width / kDx) - 1.0 / 6)) < 1e-12);
    }
  }
  CHECK_THROWS_AS(ParticleKernel(g, kFrame, 0.9 * kDx, {}), std::invalid_argument);
}

TEST_CASE("Kernel: constant and linear fields are interpolated exactly", "[coupling]") {
  SECTION("a constant anywhere, walls, solids and seams included") {
    for (const Grid& g :
         {Grid(20, 8, 12, {true, true, false}), Grid(14, 12, 10, {false, false, true})}) {
      const auto solid = block_mask(g, {8, 2, 0}, {12, 5, 4});
      const std::vector<Vec3> x = awkward_positions(g, {10, 3, 2});
      const Vec3 u0(0.3, -1.2, 2.5);  // [m/s]
      for (double width : {kDx, 6 * kDx}) {
        ParticleKernel kernel(g, kFrame, width, solid);
        kernel.locate(x);
        std::vector<Vec3> field(std::size_t(g.cells()), u0), at;
        for (std::size_t c = 0; c < field.size(); ++c)
          if (solid[c]) field[c] = Vec3(1e3, 1e3, 1e3);  // never read
        kernel.interpolate(field, at);
        double err = 0;
        for (const Vec3& v : at) err = std::max(err, (v - u0).norm());
        INFO("width " << width / kDx << " dx, max error " << err);
        // The weights of a particle sum to 1 up to the round-off of ~110 multiply-adds.
        CHECK(err < 1e-14 * u0.norm());
      }
    }
  }
  SECTION("a linear field where the kernel reaches only gas cells") {
    // Symmetric taps (sum_k k g(k) = 0) map a linear field onto itself at every cell, and
    // trilinear weights reproduce x_p: exact. Walls on all faces, so the field is not wrapped.
    const Grid g(30, 28, 26, {false, false, false});
    const double width = 2 * kDx;
    ParticleKernel kernel(g, kFrame, width, {});
    const int reach = kernel.half_taps() + 1;
    std::mt19937_64 rng(5);
    std::vector<Vec3> x(300);
    for (Vec3& p : x) {
      Vec3 l;
      for (int a = 0; a < 3; ++a)
        l[a] = std::uniform_real_distribution<double>(reach, g.extent(a) - 1 - reach)(rng);
      p = kFrame.to_si(l);
    }
    kernel.locate(x);
    const double p0 = 101325;              // [Pa]
    const Vec3 grad(120.0, -340.0, 55.0);  // [Pa/m]
    std::vector<double> p(std::size_t(g.cells())), at;
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int xx = 0; xx < g.nx(); ++xx)
          p[std::size_t(g.compact_index(xx, y, z))] =
              p0 + grad.dot(kFrame.cell_centre(xx, y, z) - kFrame.origin);
    kernel.interpolate(p, at);
    double err = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
      err = std::max(err, std::abs(at[k] - (p0 + grad.dot(x[k] - kFrame.origin))));
    INFO("max error " << err << " Pa");
    // Round-off of values near p0: a few hundred operations at 1.1e-16 p0 each.
    CHECK(err < 1e-12 * p0);
  }
}

TEST_CASE("Kernel: the pressure gradient of a linear field is exact up to walls and solids",
          "[coupling]") {
  // Central differences inside, one-sided next to a wall or solid: both exact for a linear p, so
  // the cell gradient is the constant everywhere and its interpolation (weights summing to 1)
  // is too, also at particles touching walls.
  const Grid g(20, 8, 12, {false, true, false});
  const auto solid = block_mask(g, {8, 2, 0}, {12, 5, 4});
  ParticleKernel kernel(g, kFrame, 1.5 * kDx, solid);
  const Vec3 grad(-2.0e4, 0.0, -11.8);  // [Pa/m]; uniform in y (periodic)
  std::vector<double> p(std::size_t(g.cells()));
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        p[std::size_t(g.compact_index(x, y, z))] =
            1e5 + grad.dot(kFrame.cell_centre(x, y, z) - kFrame.origin);
  std::vector<Vec3> cell_grad, at;
  kernel.pressure_gradient(p, cell_grad);
  double err = 0;
  for (std::size_t c = 0; c < p.size(); ++c)
    err = std::max(err, solid[c] ? cell_grad[c].norm() : (cell_grad[c] - grad).norm());
  // p ~ 1e5 Pa differenced over dx = 2e-4 m: round-off 1e5 x 1.1e-16 / 2e-4 = 6e-8 Pa/m per
  // difference; 1e-6 Pa/m leaves a factor 16.
  CHECK(err < 1e-6);
  std::vector<Vec3> x = awkward_positions(Grid(20, 8, 12, {true, true, false}), {10, 3, 2});
  kernel.locate(x);
  kernel.interpolate(cell_grad, at);
  double err_p = 0;
  for (const Vec3& v : at) err_p = std::max(err_p, (v - grad).norm());
  CHECK(err_p < 1e-6);
}

TEST_CASE("Kernel: a particle moving across cells leaves a continuous eps history", "[coupling]") {
  // Within a cell K_p is multilinear in the offset f (trilinear weights of fixed filter taps), so
  // moving by delta (lattice units) changes a cell's weight by at most
  //   |dK| <= (|delta_x| + |delta_y| + |delta_z|) D g(0)^2,  D = max_k |g(k + 1) - g(k)|,
  // per step, across cell boundaries too (the weights agree there). At the narrowest width
  // (sigma = dx) and a particle of d = dx this bounds the eps change per step of 2.5e-3 dx; a
  // nearest-cell map would jump by V_p / dx^3 = 0.52 once per cell crossing.
  const int n = 12;
  const Grid g(n, n, n);
  ParticleKernel kernel(g, kFrame, kDx, {});
  const auto& t = kernel.taps();
  const int h = kernel.half_taps();
  auto tap = [&](int k) { return std::abs(k) <= h ? t[std::size_t(std::abs(k))] : 0.0; };
  double dmax = 0;
  for (int k = -h - 1; k <= h; ++k) dmax = std::max(dmax, std::abs(tap(k + 1) - tap(k)));
  const double r = 0.5 * kDx, vp = sphere_volume(r);
  const Vec3 dir = Vec3(1.0, 0.7, 0.4).normalized(), start(4.3, 4.6, 4.9);
  const double step = 2.5e-3;  // [cells]
  const int steps = 1000;      // 2.5 cells: crosses cell faces on all three axes
  const double bound = vp / (kDx * kDx * kDx) * step * dir.cwiseAbs().sum() * dmax * t[0] * t[0];
  std::vector<double> eps, last;
  double worst = 0;
  for (int s = 0; s <= steps; ++s) {
    kernel.locate(std::vector<Vec3>{kFrame.to_si(start + s * step * dir)});
    kernel.gas_fraction(std::vector<double>{r}, kDefaultEpsMin, eps);
    if (s > 0)
      for (std::size_t c = 0; c < eps.size(); ++c)
        worst = std::max(worst, std::abs(eps[c] - last[c]));
    last = eps;
  }
  INFO("max eps change per step " << worst << ", bound " << bound << ", nearest-cell jump "
                                  << vp / (kDx * kDx * kDx));
  CHECK(worst > 0.2 * bound);                  // the bound is not vacuous: the motion does move eps
  CHECK(worst <= bound * (1 + 1e-9) + 1e-15);  // plus round-off of the weights
}

TEST_CASE("Kernel: clipping reports the count and the first clipped cell", "[coupling]") {
  // One particle at a cell centre (f = 0): all its weight starts in that cell, so
  // phi(c) = V_p g(dx) g(dy) g(dz) / dx^3, with the taps as published. V_p is chosen so that the
  // centre cell has phi = 0.9; the cells with 1 - phi < eps_min are counted from the taps.
  const int n = 16;
  const Grid g(n, n, n);
  ParticleKernel kernel(g, kFrame, kDx, {});
  const auto& t = kernel.taps();
  const int h = kernel.half_taps();
  const double phi_centre = 0.9, eps_min = 0.5;
  const double vp = phi_centre / (t[0] * t[0] * t[0]) * kDx * kDx * kDx;
  // z = 12: with 2 threads the clipped cells all lie in the second thread's half of the cells,
  // so the first thread's partial results stay the reduction's identities.
  const int cx = 5, cy = 6, cz = 12;
  kernel.locate(std::vector<Vec3>{kFrame.cell_centre(cx, cy, cz)});
  // The report is reduced over the cells in parallel (16^3 cells: at the serial threshold);
  // 1 and 2 threads must give the same field, count, first cell and lowest value.
  REQUIRE(g.cells() >= ParticleKernel::kMinParallelCells);
  std::vector<double> eps, eps2;
  PorosityReport r, r2;
  {
    struct RestoreThreads {  // also when a call throws
      int saved = omp_get_max_threads();
      ~RestoreThreads() { omp_set_num_threads(saved); }
    } restore;
    omp_set_num_threads(1);
    r = kernel.gas_fraction(std::vector<double>{std::cbrt(vp * 3 / (4 * kPi))}, eps_min, eps);
    omp_set_num_threads(2);
    r2 = kernel.gas_fraction(std::vector<double>{std::cbrt(vp * 3 / (4 * kPi))}, eps_min, eps2);
  }
  CHECK(eps2 == eps);
  CHECK(r2.clipped == r.clipped);
  CHECK(r2.first == r.first);
  CHECK(r2.lowest == r.lowest);
  Index expect = 0;
  std::array<int, 3> first = {-1, -1, -1};
  for (int dz = -h; dz <= h; ++dz)
    for (int dy = -h; dy <= h; ++dy)
      for (int dx = -h; dx <= h; ++dx) {
        const double phi = phi_centre * t[std::size_t(std::abs(dx))] *
                           t[std::size_t(std::abs(dy))] * t[std::size_t(std::abs(dz))] /
                           (t[0] * t[0] * t[0]);
        // Margins: no cell within 1e-6 of the threshold, so round-off cannot flip a count.
        REQUIRE(std::abs(1 - phi - eps_min) > 1e-6);
        if (1 - phi < eps_min && expect++ == 0) first = {cx + dx, cy + dy, cz + dz};
      }
  INFO("taps " << t[0] << " " << t[1] << " " << t[2] << "; expected " << expect << " clipped");
  CHECK(expect > 1);  // the centre and at least its face neighbours: a non-trivial count
  CHECK(r.clipped == expect);
  CHECK(r.first == first);
  CHECK(std::abs(r.lowest - (1 - phi_centre)) < 1e-13);
  CHECK(eps[std::size_t(g.compact_index(cx, cy, cz))] == eps_min);
  const PorosityReport none = kernel.gas_fraction(std::vector<double>{1e-3 * kDx}, eps_min, eps);
  CHECK(none.clipped == 0);
  CHECK(none.first == std::array<int, 3>{-1, -1, -1});
}

TEST_CASE("Kernel: deposition and interpolation are bitwise the same at 1 and 2 threads",
          "[coupling]") {
  // Equivalence test (not validation): the thread count must not change a bit. Also the fused
  // four-component calls the exchange uses (a scalar and a vector in one filter) against the
  // separate calls.
  const Grid g(20, 18, 16, {true, false, false});
  const auto solid = block_mask(g, {4, 5, 0}, {9, 9, 6});
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 1.0);
  std::vector<Vec3> x(3000), f(x.size()), field(std::size_t(g.cells()));
  std::vector<double> radii(x.size()), p(field.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = kFrame.to_si(Vec3(20 * u(rng), 18 * u(rng), 16 * u(rng)));
    f[k] = Vec3(u(rng), u(rng), u(rng));
    radii[k] = 0.6 * kDx * (1 + u(rng));
  }
  for (std::size_t c = 0; c < field.size(); ++c) {
    field[c] = Vec3(u(rng), u(rng), u(rng));
    p[c] = 1e5 * u(rng);
  }
  struct Out {
    std::vector<double> eps, vol, vol_fused, eps_p, eps_p_fused;
    std::vector<Vec3> force, u, grad, force_fused, grad_fused;
  };
  // Sizes above the thresholds below which the loops run serially.
  REQUIRE(g.cells() >= ParticleKernel::kMinParallelCells);
  REQUIRE(x.size() >= ParticleKernel::kMinParallelParticles);
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    ParticleKernel kernel(g, kFrame, 1.7 * kDx, solid);
    kernel.locate(x);
    Out o;
    kernel.gas_fraction(radii, kDefaultEpsMin, o.eps);
    kernel.deposit(f, o.force);
    kernel.interpolate(field, o.u);
    std::vector<Vec3> cell_grad;
    kernel.pressure_gradient(p, cell_grad);
    kernel.interpolate(cell_grad, o.grad);
    kernel.deposit(radii, o.vol);
    kernel.deposit(radii, f, o.vol_fused, o.force_fused);
    kernel.interpolate(o.eps, o.eps_p);
    kernel.interpolate(o.eps, cell_grad, o.eps_p_fused, o.grad_fused);
    return o;
  };
  const int saved = omp_get_max_threads();
  const Out one = run(1), two = run(2);
  omp_set_num_threads(saved);
  auto same = [](const auto& a, const auto& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
  };
  CHECK(same(one.eps, two.eps));
  CHECK(same(one.force, two.force));
  CHECK(same(one.u, two.u));
  CHECK(same(one.grad, two.grad));
  for (const Out* o : {&one, &two}) {
    CHECK(same(o->vol, o->vol_fused));
    CHECK(same(o->force, o->force_fused));
    CHECK(same(o->eps_p, o->eps_p_fused));
    CHECK(same(o->grad, o->grad_fused));
  }
  CHECK(same(one.vol, two.vol));
}

TEST_CASE(
    "Kernel: the parallel gather is bitwise the same at 1 and 2 threads on thin periodic "
    "and walled boxes",
    "[coupling]") {
  // Equivalence test (not validation): each thread writes whole cell planes, fed by the bin
  // planes of the lower trilinear plane z (corners 0-3) and z - 1 (corners 4-7). The edge cases
  // of that map: periodic z with 1, 2 and 3 planes (plane 0 fed twice by one bin plane; two
  // planes feeding each other), and walls in z with particles below and above the box (clamped
  // to the faces). Above the particle count where the loops run in parallel; under the
  // sanitizers this also checks the bin ranges read.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Grid& g :
       {Grid(14, 12, 1, {true, true, true}), Grid(14, 12, 2, {true, true, true}),
        Grid(14, 12, 3, {true, true, true}), Grid(14, 12, 5, {true, true, false})}) {
    std::vector<Vec3> x(2000), f(x.size());
    std::vector<double> q(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
      // z from a cell below the box to a cell above it
      x[k] = kFrame.to_si(Vec3(14 * u(rng), 12 * u(rng), (g.nz() + 2) * u(rng) - 1));
      f[k] = Vec3(u(rng) - 0.5, u(rng), -u(rng));
      q[k] = u(rng);
    }
    REQUIRE(x.size() >= ParticleKernel::kMinParallelParticles);
    auto run = [&](int threads) {
      omp_set_num_threads(threads);
      ParticleKernel kernel(g, kFrame, 1.3 * kDx, {});
      kernel.locate(x);
      std::vector<double> dq;
      std::vector<Vec3> dv;
      kernel.deposit(q, f, dq, dv);
      return std::make_pair(dq, dv);
    };
    const int saved = omp_get_max_threads();
    const auto one = run(1), two = run(2);
    omp_set_num_threads(saved);
    CHECK(one.first == two.first);
    REQUIRE(one.second.size() == two.second.size());
    CHECK(std::memcmp(one.second.data(), two.second.data(), one.second.size() * sizeof(Vec3)) == 0);
    // Not a copy of an empty field: the deposits hold the particles' totals (sum_c out dx^3 =
    // sum_p q_p to round-off, kernel.hpp).
    double total = 0, want = 0;
    for (double v : one.first) total += v * std::pow(kDx, 3);
    for (double v : q) want += v;
    CHECK(std::abs(total - want) < 1e-12 * want);
  }
}

TEST_CASE("Kernel: skipping the planes that hold no particle changes no bit", "[coupling]") {
  // Equivalence test (not validation): the filter passes run only on the z planes the particles
  // touch or reach (kernel.hpp). A bed in the lower planes is compared with the same bed plus
  // spectators of zero volume, force and weight in every plane, which make every plane active:
  // the cell fields and the values read at the bed's particles must agree bit for bit. Two boxes:
  // walls in z with the bed on the lower face, and periodic z (the bed across the seam) with a
  // kernel wider than a quarter of the box.
  struct Box {
    Grid grid;
    double width;       // sigma [cells]
    double z_lo, z_hi;  // the bed's extent [lattice z]
  };
  for (const Box& b : {Box{Grid(12, 10, 40, {true, true, false}), 2.0, -0.5, 5.0},
                       Box{Grid(12, 10, 24, {true, true, true}), 3.0, 21.0, 27.0}}) {
    const Grid& g = b.grid;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> bed;
    for (int k = 0; k < 400; ++k)
      bed.push_back(kFrame.to_si(
          Vec3(12 * u(rng) - 0.5, 10 * u(rng) - 0.5, b.z_lo + (b.z_hi - b.z_lo) * u(rng))));
    std::vector<Vec3> all = bed;
    for (int z = 0; z < g.nz(); ++z) all.push_back(kFrame.to_si(Vec3(5.3, 4.1, z + 0.2)));
    std::vector<Vec3> field(std::size_t(g.cells()));
    for (Vec3& v : field) v = Vec3(u(rng), u(rng), u(rng)) - Vec3(0.5, 0.5, 0.5);

    struct Out {
      std::vector<double> eps;
      std::vector<Vec3> force, at_bed;
    };
    auto run = [&](const std::vector<Vec3>& x) {
      ParticleKernel kernel(g, kFrame, b.width * kDx);
      kernel.locate(x);
      std::vector<double> radii(x.size(), 0.0);
      std::vector<Vec3> f(x.size(), Vec3::Zero());
      for (std::size_t k = 0; k < bed.size(); ++k) {
        radii[k] = 0.4 * kDx * (1 + 0.3 * std::sin(double(k)));
        f[k] = Vec3(std::cos(double(k)), 1.0, -0.5 * std::sin(double(k)));
      }
      Out o;
      kernel.gas_fraction(radii, kDefaultEpsMin, o.eps);
      kernel.deposit(f, o.force);
      kernel.interpolate(field, o.at_bed);
      o.at_bed.resize(bed.size());
      return o;
    };
    const Out alone = run(bed), crowded = run(all);
    auto same = [](const auto& a, const auto& c) {
      return a.size() == c.size() && std::memcmp(a.data(), c.data(), a.size() * sizeof(a[0])) == 0;
    };
    INFO("nz " << g.nz() << ", periodic z " << g.periodic(2));
    CHECK(same(alone.eps, crowded.eps));
    CHECK(same(alone.force, crowded.force));
    CHECK(same(alone.at_bed, crowded.at_bed));
    // The bed's force reaches a plane beyond the ones it touches (the test would pass trivially if
    // nothing were deposited above them).
    const auto top = std::size_t(g.compact_index(5, 5, int(std::floor(b.z_hi)) % g.nz()));
    CHECK(crowded.force[top].norm() > 0);
  }
}

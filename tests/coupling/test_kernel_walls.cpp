// The coupling kernel at walls, solid cells and domain faces (coupling/kernel.hpp): a bed of
// uniform solid fraction deposits a uniform field up to them, a particle moving into a wall keeps
// its deposited volume, and settled packed beds in a thin walled box and in a cylinder read the
// gas fraction that binning the particles' volume into the cells gives.
#include <catch2/catch.hpp>

#include "coupling/kernel.hpp"
#include "dem/dem_solver.hpp"
#include "helpers/dem_setup.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

using namespace lbdem;
using namespace lbdem::coupling;
using lbm::Grid;
using lbm::LatticeFrame;

namespace {

double sphere_volume(double r) {
  return 4.0 / 3.0 * kPi * r * r * r;
}

// One particle at every gas cell centre (trilinear weight 1 on its own cell): a source that is
// uniform on the gas cells and zero on the solid ones.
std::vector<Vec3> cell_centres(const Grid& g, const LatticeFrame& f,
                               const std::vector<std::uint8_t>& solid) {
  std::vector<Vec3> x;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int i = 0; i < g.nx(); ++i)
        if (solid.empty() || !solid[std::size_t(g.compact_index(i, y, z))])
          x.push_back(f.to_si(Vec3(i, y, z)));
  return x;
}

// Cells outside a cylinder of radius rc about the z axis through (cx, cy) [cells] are solid.
std::vector<std::uint8_t> cylinder_mask(const Grid& g, double cx, double cy, double rc) {
  std::vector<std::uint8_t> m(std::size_t(g.cells()), 0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        m[std::size_t(g.compact_index(x, y, z))] = std::hypot(x - cx, y - cy) > rc;
  return m;
}

// The solid fraction per cell from the particles' own volume: each sphere sampled on a 16^3
// lattice over its bounding cube, its volume shared among the cells its inside points fall in
// (points outside the box are dropped: a particle overlaps a wall by less than 1e-3 of its
// volume here). Converges to the exact sphere-cell intersection as the lattice is refined.
// accessible: for a grid centred on a particle box of other size, the part of the box each cell
// stands for (ParticleKernel::accessible()): a point beyond the grid's face belongs to the outer
// cell, and each cell's volume is divided by its part, a dx^3.
std::vector<double> binned_solid_fraction(const Grid& g, const LatticeFrame& f,
                                          const std::vector<Vec3>& x, const std::vector<double>& r,
                                          const std::vector<double>* accessible = nullptr) {
  constexpr int kS = 16;
  std::vector<double> phi(std::size_t(g.cells()), 0.0);
  std::vector<Vec3> pts;
  for (std::size_t p = 0; p < x.size(); ++p) {
    pts.clear();
    for (int i = 0; i < kS; ++i)
      for (int j = 0; j < kS; ++j)
        for (int k = 0; k < kS; ++k) {
          const Vec3 u = (Vec3(i, j, k) + Vec3::Constant(0.5)) * (2.0 / kS) - Vec3::Ones();
          if (u.squaredNorm() <= 1) pts.push_back(x[p] + r[p] * u);
        }
    const double share = sphere_volume(r[p]) / double(pts.size()) / std::pow(f.dx, 3);
    for (const Vec3& q : pts) {
      const Vec3 l = f.to_lattice(q) + Vec3::Constant(0.5);  // cell i spans [i, i + 1)
      int c[3] = {int(std::floor(l.x())), int(std::floor(l.y())), int(std::floor(l.z()))};
      if (accessible)  // the points lie in the particles' box (less the overlaps)
        for (int a = 0; a < 3; ++a) c[a] = std::clamp(c[a], 0, g.extent(a) - 1);
      if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[0] >= g.nx() || c[1] >= g.ny() || c[2] >= g.nz())
        continue;
      phi[std::size_t(g.compact_index(c[0], c[1], c[2]))] += share;
    }
  }
  if (accessible)
    for (std::size_t c = 0; c < phi.size(); ++c) phi[c] /= (*accessible)[c];
  return phi;
}

struct Bed {
  std::vector<Vec3> x;
  std::vector<double> r;
};

// Beads of radius r poured from a jittered lattice (spacing 2.2 r) into the region lo..hi and
// settled under gravity with soft, well-damped linear springs (e = 0.3, mu = 0.3: a random loose
// to close packing, solid fraction about 0.58-0.62). The walls are given by the caller; inside
// tells the lattice sites that lie within them.
template <class Inside>
Bed settle(const std::vector<dem::Wall>& walls, Vec3 lo, Vec3 hi, double r, int count, double zmax,
           Inside inside) {
  auto m = test::glass(0.3, 0.3);
  m.stiffness = 200;  // [N/m]: overlap under a 20 mm bed about 3e-3 d, t_c = 0.24 ms
  const double mass = m.density * sphere_volume(r);
  const double tc = kPi * std::sqrt(0.5 * mass / m.stiffness);
  auto s = test::settings(tc / 20, Vec3(0, 0, -9.81));
  s.contact.normal = "linear";
  s.domain.lo = lo - Vec3::Constant(2 * r);
  s.domain.hi = Vec3(hi.x(), hi.y(), zmax) + Vec3::Constant(2 * r);
  dem::DemSolver solver(s, {m});
  for (const auto& w : walls) solver.add_wall(w);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.05 * r, 0.05 * r);
  const double a = 2.2 * r;
  int n = 0;
  for (double z = lo.z() + r; n < count && z < zmax; z += a)
    for (double y = lo.y() + 1.1 * r; n < count && y <= hi.y() - 1.1 * r; y += a)
      for (double x = lo.x() + 1.1 * r; n < count && x <= hi.x() - 1.1 * r; x += a) {
        const Vec3 p(x + jitter(rng), y + jitter(rng), z + jitter(rng));
        if (!inside(p)) continue;
        solver.add_particle(p, Vec3::Zero(), r, 0);
        ++n;
      }
  REQUIRE(n == count);
  const int steps = int(std::ceil(0.2 / s.dt));  // falls of 10 mm take 45 ms; the rest settles
  for (int k = 0; k < steps; ++k) solver.step();
  double v2 = 0;
  for (const auto& v : solver.particles().v) v2 += v.squaredNorm();
  // [m/s]: at rest but for a few rattlers (a bead moving at this speed crosses a tenth of a cell
  // in the 0.1 s the bed had to come to rest).
  CHECK(std::sqrt(v2 / double(count)) < 5e-3);
  return {solver.particles().x, solver.particles().radius};
}

// Mean of a cell field over the gas cells where pick(x, y, z) holds.
template <class Pick>
double mean_over(const Grid& g, const std::vector<double>& v,
                 const std::vector<std::uint8_t>& solid, Pick pick) {
  double s = 0;
  int n = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const auto c = std::size_t(g.compact_index(x, y, z));
        if ((solid.empty() || !solid[c]) && pick(x, y, z)) s += v[c], ++n;
      }
  REQUIRE(n > 0);
  return s / n;
}

}  // namespace

TEST_CASE("Kernel walls: a uniform source deposits a uniform field up to faces and solids",
          "[coupling]") {
  // Cell centres carry the same volume: the source is uniform on the gas cells, so the deposit
  // must be too. Walls on every face, or periodic x with walls in y and z, kernels narrower and
  // wider than the box (sigma = 1.5 cells on a 3-cell axis), with and without solid cells.
  const LatticeFrame f{Vec3(1e-3, 0, -2e-3), 1e-3};
  const double q = 0.4 * std::pow(f.dx, 3);  // solid fraction 0.4 per particle and cell
  struct Case {
    Grid grid;
    double sigma;  // [cells]
    bool cylinder;
  };
  constexpr std::array<bool, 3> kWalls = {false, false, false};
  const Case cases[] = {{Grid(12, 3, 10, kWalls), 1.5, false},
                        {Grid(12, 3, 10, {true, false, false}), 1.0, false},
                        {Grid(9, 9, 6, kWalls), 2.0, false},
                        {Grid(16, 16, 5, {false, false, true}), 1.0, true},
                        {Grid(16, 16, 5, kWalls), 2.0, true}};
  for (const Case& c : cases) {
    const auto solid =
        c.cylinder ? cylinder_mask(c.grid, 7.5, 7.5, 7.0) : std::vector<std::uint8_t>{};
    ParticleKernel k(c.grid, f, c.sigma * f.dx, solid);
    const auto x = cell_centres(c.grid, f, solid);
    k.locate(x);
    std::vector<double> phi;
    k.deposit(std::vector<double>(x.size(), q), phi);
    double total = 0, worst = 0;
    for (std::size_t i = 0; i < phi.size(); ++i) {
      total += phi[i] * std::pow(f.dx, 3);
      if (solid.empty() || !solid[i])
        worst = std::max(worst, std::abs(phi[i] - 0.4));
      else
        CHECK(phi[i] == 0);
    }
    INFO("grid " << c.grid.nx() << "x" << c.grid.ny() << "x" << c.grid.nz() << ", sigma " << c.sigma
                 << ", cylinder " << c.cylinder << ", balance error " << k.balance_error());
    // Without solids the mirrored filter is doubly stochastic: round-off. With them, the rows sum
    // to 1 within the balance tolerance (1e-12 relative, so 0.4e-12 here) plus round-off.
    CHECK(worst < 1e-11);
    CHECK(total == Approx(q * double(x.size())).epsilon(1e-13));
  }
}

TEST_CASE("Kernel walls: interpolation is the transpose of deposition at faces and solids",
          "[coupling]") {
  // sum_c deposit(q)(c) f(c) dx^3 = sum_p q_p interpolate(f)(p) for any q and f: the mirrored,
  // balanced filter enters both as one matrix, so a wrong reflection or scaling on one side
  // breaks it. Walls on every face, a kernel wider than the 3-cell axis, a solid cylinder, and
  // particles on and beyond the faces; random q and f, to 1e-13 of sum |q| |f|.
  const LatticeFrame f{Vec3(2e-3, -1e-3, 0), 1e-3};
  const Grid g(12, 3, 9, {false, false, false});
  std::vector<std::uint8_t> solid(std::size_t(g.cells()), 0);
  for (int z = 0; z < g.nz(); ++z)
    for (int x = 0; x < g.nx(); ++x)
      if (std::hypot(x - 8.0, z - 4.0) < 1.6)
        for (int y = 0; y < g.ny(); ++y) solid[std::size_t(g.compact_index(x, y, z))] = 1;
  ParticleKernel k(g, f, 2.5 * f.dx, solid);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.8, 1.0), val(-1.0, 1.0);
  std::vector<Vec3> x;
  for (int p = 0; p < 300; ++p)
    x.push_back(f.to_si(Vec3(u(rng) * g.nx(), u(rng) * g.ny(), u(rng) * g.nz())));
  k.locate(x);
  std::vector<double> q(x.size()), field(std::size_t(g.cells()));
  for (double& v : q) v = val(rng);
  for (double& v : field) v = val(rng);
  std::vector<double> dep, at;
  k.deposit(q, dep);
  k.interpolate(field, at);
  double lhs = 0, rhs = 0, scale = 0;
  for (std::size_t c = 0; c < dep.size(); ++c) lhs += dep[c] * field[c] * std::pow(f.dx, 3);
  for (std::size_t p = 0; p < q.size(); ++p) rhs += q[p] * at[p], scale += std::abs(q[p]);
  CHECK(std::abs(lhs - rhs) < 1e-13 * scale);
}

TEST_CASE("Kernel walls: a particle moving into a wall or a solid keeps its volume", "[coupling]") {
  // From the middle of the box to touching the wall face (and beyond, where the DEM would not let
  // it go), and along a row towards a solid block: the deposited volume stays the particle's.
  const LatticeFrame f{Vec3::Zero(), 1e-3};
  const Grid g(10, 6, 8, {false, false, false});
  std::vector<std::uint8_t> solid(std::size_t(g.cells()), 0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y) solid[std::size_t(g.compact_index(9, y, z))] = 1;
  ParticleKernel k(g, f, 2.0 * f.dx, solid);
  const double r = 0.4e-3, v = sphere_volume(r);
  for (double t = 4.0; t >= -0.7; t -= 0.05) {
    for (const Vec3& lx : {Vec3(4.2, t, 3.7), Vec3(3.3, 2.5, t), Vec3(8.0 - t, 2.2, 3.1)}) {
      k.locate(std::vector<Vec3>{f.to_si(lx)});
      std::vector<double> phi;
      k.deposit(std::vector<double>{v}, phi);
      const double total = std::accumulate(phi.begin(), phi.end(), 0.0) * std::pow(f.dx, 3);
      INFO("lattice position " << lx.transpose());
      CHECK(total == Approx(v).epsilon(1e-13));
    }
  }
}

TEST_CASE("Kernel walls: a settled bed in a 3-cell-thin walled box reads the binned gas fraction",
          "[coupling][slow]") {
  // A pseudo-2-D bed: 1.2 mm beads in a 20 x 10 mm walled box, three 3.33 mm gas cells across its
  // thickness, the default kernel width (sigma = max(dx, 2 d) = dx). Binning the beads' volume
  // gives each layer of cells parallel to a wall its solid fraction (0.545 at the y walls, 0.58
  // in the middle: the beads order against a wall); the kernel, which smooths over sigma and
  // mirrors at the walls, must give each layer the same within 0.04. The layers hold 18-24 cells,
  // about 500 beads, so their sampling noise is about 0.01; a kernel one cell wide on a 3-cell
  // axis evens out most of the wall-to-middle contrast, which is 0.04 here (the kernel reads
  // 0.531-0.567 in every cell of the bed). The former renormalisation over the gas cells
  // (G / Z(c), no mirror) read 0.68 in the middle layer and 0.52 at the walls on this bed, single
  // cells up to 0.76, 10 of them clipped at eps_min.
  const double r = 0.6e-3, dx = 1e-2 / 3;
  const Grid g(6, 3, 9, {false, false, false});  // 20 x 10 x 30 mm
  const LatticeFrame f{Vec3::Zero(), dx};        // cell (0, 0, 0) spans [0, dx)^3
  const Vec3 lo = Vec3::Zero(), hi(0.02, 0.01, 0.03);
  const std::vector<dem::Wall> walls = {
      test::plane_wall(lo, Vec3::UnitZ()), test::plane_wall(lo, Vec3::UnitX()),
      test::plane_wall(hi, -Vec3::UnitX()), test::plane_wall(lo, Vec3::UnitY()),
      test::plane_wall(hi, -Vec3::UnitY())};
  const Bed bed = settle(walls, lo, hi, r, 2400, 0.06, [](const Vec3&) { return true; });
  const auto binned = binned_solid_fraction(g, f, bed.x, bed.r);
  ParticleKernel k(g, f, default_kernel_width(dx, 2 * r));
  k.locate(bed.x);
  std::vector<double> eps;
  const PorosityReport rep = k.gas_fraction(bed.r, kDefaultEpsMin, eps);
  CHECK(rep.clipped == 0);
  std::vector<double> phi(eps.size());
  for (std::size_t c = 0; c < eps.size(); ++c) phi[c] = 1 - eps[c];
  // The bed's interior in z: above the floor cell, two cells below the surface.
  double top = 0;
  for (const Vec3& x : bed.x) top = std::max(top, x.z());
  const int z1 = int(std::floor(top / dx)) - 2;
  REQUIRE(z1 >= 3);
  const auto in_bed = [&](int z) { return z >= 1 && z < z1; };
  for (int y = 0; y < g.ny(); ++y) {
    const auto layer = [&](int, int yy, int z) { return yy == y && in_bed(z); };
    const double want = mean_over(g, binned, {}, layer), got = mean_over(g, phi, {}, layer);
    INFO("y layer " << y << ": binned " << want << ", kernel " << got);
    CHECK(want > 0.5);
    CHECK(got == Approx(want).margin(0.04));
  }
  for (int x = 0; x < g.nx(); ++x) {
    const auto layer = [&](int xx, int, int z) { return xx == x && in_bed(z); };
    const double want = mean_over(g, binned, {}, layer), got = mean_over(g, phi, {}, layer);
    INFO("x layer " << x << ": binned " << want << ", kernel " << got);
    CHECK(want > 0.5);
    CHECK(got == Approx(want).margin(0.04));
  }
}

TEST_CASE("Kernel walls: a settled bed in a cylinder reads the binned gas fraction",
          "[coupling][slow]") {
  // 1.2 mm beads in a cylinder of 16 mm diameter on a 2 mm grid, the cylinder voxelised as the
  // cells whose centres lie inside it (a staircase, as the gas sees it). Binned volume in a solid
  // cell belongs to the gas cell next to it, so the comparison is by rings: the outer ring (gas
  // cells within 1.5 cells of the wall) holds the binned volume of its cells and of the solid
  // cells outside it, over its gas volume; the inner disc its own. Tolerance 0.03: each ring
  // holds over 400 beads (sampling noise 0.01), and the kernel smooths the wall layer into both.
  const double r = 0.6e-3, dx = 2e-3, rc = 8e-3;
  const Grid g(9, 9, 12, {false, false, false});  // 18 x 18 x 24 mm, axis at (9, 9) mm
  const LatticeFrame f{Vec3::Zero(), dx};
  const double cx = 9e-3, cy = 9e-3;
  dem::Wall cyl;
  cyl.name = "cylinder";
  dem::CylinderWall cw;
  cw.origin = Vec3(cx, cy, 0);
  cw.radius = rc;
  cw.inside = true;
  cyl.shape = cw;
  const Bed bed =
      settle({test::plane_wall(Vec3::Zero(), Vec3::UnitZ()), cyl}, Vec3(cx - rc, cy - rc, 0),
             Vec3(cx + rc, cy + rc, 0), r, 2000, 0.07,
             [&](const Vec3& p) { return std::hypot(p.x() - cx, p.y() - cy) < rc - 1.1 * r; });
  // Lattice coordinates of the axis: cell centre i sits at (i + 1/2) dx.
  const auto solid = cylinder_mask(g, cx / dx - 0.5, cy / dx - 0.5, rc / dx);
  const auto binned = binned_solid_fraction(g, f, bed.x, bed.r);
  ParticleKernel k(g, f, default_kernel_width(dx, 2 * r), solid);
  k.locate(bed.x);
  std::vector<double> eps;
  const PorosityReport rep = k.gas_fraction(bed.r, kDefaultEpsMin, eps);
  CHECK(rep.clipped == 0);
  double top = 0;
  for (const Vec3& x : bed.x) top = std::max(top, x.z());
  const int z1 = int(std::floor(top / dx)) - 2;
  REQUIRE(z1 >= 3);
  const auto radius = [&](int x, int y) {
    return std::hypot(x - (cx / dx - 0.5), y - (cy / dx - 0.5));
  };
  const double ring = rc / dx - 1.5;
  // Binned volume per ring, the outer one with the solid cells' share, over the ring's gas cells.
  double vin = 0, vout = 0, kin = 0, kout = 0;
  int nin = 0, nout = 0;
  for (int z = 1; z < z1; ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const auto c = std::size_t(g.compact_index(x, y, z));
        const bool outer = radius(x, y) >= ring;
        (outer ? vout : vin) += binned[c];
        if (solid[c]) continue;
        (outer ? kout : kin) += 1 - eps[c];
        ++(outer ? nout : nin);
      }
  INFO("inner: binned " << vin / nin << ", kernel " << kin / nin << "; outer: binned "
                        << vout / nout << ", kernel " << kout / nout << "; balance error "
                        << k.balance_error());
  CHECK(vin / nin > 0.5);
  CHECK(kin / nin == Approx(vin / nin).margin(0.03));
  CHECK(kout / nout == Approx(vout / nout).margin(0.03));
}

TEST_CASE(
    "Kernel on a grid centred on a box of other size: a uniform bed reads its solid fraction "
    "in every cell",
    "[coupling]") {
  // scenarios/common/fluid_config.cpp centres round(L/dx) cells on a box edge L, so the outer
  // cells stand for 0.75-1.25 cells of the particles' box. Here the box's faces lie 0.2 cells
  // beyond the grid's (the outer cells hold 1.2 cells of it) or 0.2 cells short of them (0.8),
  // both sides alike. Point particles at the centres of a 0.1-cell sub-lattice fill the box at
  // solid fraction 0.5; the sub-lattice's faces pass through the cell centres, where the trilinear
  // weights bend, so the trilinear step hands each cell exactly 0.5 a dx^3 (the midpoint rule is
  // exact on linear pieces), and binning the particles' volume into the part of the box each cell
  // stands for gives 0.5 in every cell by construction. The kernel must read 0.5 in every cell,
  // to the balance tolerance (1e-12, so 1e-10 with round-off over 10^5 particles), keep the
  // particles' volume, sum_c (1 - eps) a dx^3, to round-off, and read a constant field back
  // exactly at every particle. A kernel that ignores the box (fluid mask 1, the deposit over
  // dx^3) reads about 0.5 a in the outer cells: the first case tells it apart.
  const double dx = 1e-3, h = 0.1;  // [m], sub-lattice spacing [cells]
  const LatticeFrame f{Vec3(0.003, -0.001, 0.0), dx};
  const Grid g(6, 3, 6, {false, false, false});
  struct Case {
    std::array<double, 3> beyond;  // the box's faces beyond the grid's [cells], per axis
    double sigma;                  // [cells]
  };
  const Case cases[] = {
      {{0.2, -0.2, -0.2}, 1.0}, {{-0.2, 0.0, 0.2}, 2.0}, {{0.2, -0.2, -0.2}, 2.5}};
  bool first = true;
  for (const Case& c : cases) {
    ParticleBox box;
    int count[3];
    for (int a = 0; a < 3; ++a) {
      const double b = c.beyond[std::size_t(a)];
      box.lo[a] = f.origin[a] - b * dx;
      box.hi[a] = f.origin[a] + (g.extent(a) + b) * dx;
      count[a] = int(std::lround((g.extent(a) + 2 * b) / h));
    }
    std::vector<Vec3> x;
    for (int k = 0; k < count[2]; ++k)
      for (int j = 0; j < count[1]; ++j)
        for (int i = 0; i < count[0]; ++i)
          x.push_back(box.lo + (Vec3(i, j, k) + Vec3::Constant(0.5)) * (h * dx));
    const double q = 0.5 * std::pow(h * dx, 3);
    const std::vector<double> radii(x.size(), std::cbrt(3 * q / (4 * kPi)));
    ParticleKernel k(g, f, c.sigma * dx, {}, box);
    INFO("box beyond the grid by " << c.beyond[0] << ", " << c.beyond[1] << ", " << c.beyond[2]
                                   << " cells, sigma " << c.sigma << " cells, balance error "
                                   << k.balance_error());
    const double corner = (1 + c.beyond[0]) * (1 + c.beyond[1]) * (1 + c.beyond[2]);
    CHECK(k.accessible()[0] == Approx(corner).epsilon(1e-12));
    k.locate(x);
    std::vector<double> eps;
    const PorosityReport rep = k.gas_fraction(radii, kDefaultEpsMin, eps);
    REQUIRE(rep.clipped == 0);
    double worst = 0, volume = 0;
    for (std::size_t i = 0; i < eps.size(); ++i) {
      worst = std::max(worst, std::abs(1 - eps[i] - 0.5));
      volume += (1 - eps[i]) * k.accessible()[i] * std::pow(dx, 3);
    }
    CHECK(worst < 1e-10);
    CHECK(volume == Approx(q * double(x.size())).epsilon(1e-12));
    std::vector<double> at;
    k.interpolate(eps, at);
    double off = 0;
    for (double e : at) off = std::max(off, std::abs(e - 0.5));
    CHECK(off < 1e-10);
    if (first) {
      first = false;
      ParticleKernel plain(g, f, c.sigma * dx);
      plain.locate(x);
      plain.gas_fraction(radii, kDefaultEpsMin, eps);
      double plain_worst = 0;
      for (double e : eps) plain_worst = std::max(plain_worst, std::abs(1 - e - 0.5));
      INFO("without the box the worst cell reads " << plain_worst << " off 0.5");
      CHECK(plain_worst > 0.05);
    }
  }
}

TEST_CASE(
    "Kernel on a grid centred on a box of other size: a settled bed reads the binned solid "
    "fraction at the walls",
    "[coupling][slow]") {
  // 1.2 mm beads settled in a walled box of 13.2 x 8.8 mm, 6.6 and 4.4 cells of 2 mm: the gas
  // grid of fluid_config.cpp is 7 cells across x (its walls 0.4 mm outside the particles', the
  // outer cells stand for 0.8 of a cell of the box) and 4 across y (0.4 mm inside, 1.2 cells),
  // and the floor lies 0.4 mm below the grid's (a 30.8 mm box edge in z, 15 cells). Binning the
  // beads' volume into the part of the box each cell stands for gives each layer of cells along
  // a wall its solid fraction; the kernel must give each layer the same within 0.04, the
  // tolerance of the 3-cell box above (layers of 14-28 cells, 300-600 beads: sampling noise about
  // 0.01; the kernel, 1.2 cells wide, evens out the beads' ordering against a wall). The ordering
  // weighs most in the thinnest layer: the x wall layers, 1.6 mm of the box, bin 0.50 where the
  // bed's interior bins 0.57 and the 2.4 mm y wall layers 0.52-0.54; the kernel reads 0.53 there
  // (measured 0.035 off, the largest difference; 0.01-0.03 elsewhere). A kernel that ignored the
  // box would read about 0.8 and 1.2 times the bed's 0.58 in the wall layers, 0.12 off. The
  // particles' volume is kept to round-off.
  const double r = 0.6e-3, dx = 2e-3;
  const Vec3 lo = Vec3::Zero(), hi(0.0132, 0.0088, 0.0308);
  const Grid g(7, 4, 15, {false, false, false});
  const LatticeFrame f{Vec3(-0.4e-3, 0.4e-3, 0.4e-3), dx};  // centred on the box: the design
  const std::vector<dem::Wall> walls = {
      test::plane_wall(lo, Vec3::UnitZ()), test::plane_wall(lo, Vec3::UnitX()),
      test::plane_wall(hi, -Vec3::UnitX()), test::plane_wall(lo, Vec3::UnitY()),
      test::plane_wall(hi, -Vec3::UnitY())};
  const Bed bed = settle(walls, lo, hi, r, 1500, 0.06, [](const Vec3&) { return true; });
  ParticleKernel k(g, f, default_kernel_width(dx, 2 * r), {}, ParticleBox{lo, hi});
  CHECK(k.accessible()[std::size_t(g.compact_index(0, 0, 0))] == Approx(0.8 * 1.2 * 1.2));
  CHECK(k.accessible()[std::size_t(g.compact_index(3, 1, 5))] == 1);
  const auto binned = binned_solid_fraction(g, f, bed.x, bed.r, &k.accessible());
  k.locate(bed.x);
  std::vector<double> eps;
  const PorosityReport rep = k.gas_fraction(bed.r, kDefaultEpsMin, eps);
  CHECK(rep.clipped == 0);
  double volume = 0, want_volume = 0;
  for (std::size_t c = 0; c < eps.size(); ++c)
    volume += (1 - eps[c]) * k.accessible()[c] * std::pow(dx, 3);
  for (double rp : bed.r) want_volume += sphere_volume(rp);
  CHECK(volume == Approx(want_volume).epsilon(1e-12));
  std::vector<double> phi(eps.size());
  for (std::size_t c = 0; c < eps.size(); ++c) phi[c] = 1 - eps[c];
  // The bed's interior in z: the floor layer, up to two cells below the surface.
  double top = 0;
  for (const Vec3& x : bed.x) top = std::max(top, x.z());
  const int z1 = int(std::floor(f.to_lattice(Vec3(0, 0, top)).z() + 0.5)) - 2;
  REQUIRE(z1 >= 4);
  const auto in_bed = [&](int z) { return z >= 0 && z < z1; };
  for (int y = 0; y < g.ny(); ++y) {
    const auto layer = [&](int, int yy, int z) { return yy == y && in_bed(z); };
    const double want = mean_over(g, binned, {}, layer), got = mean_over(g, phi, {}, layer);
    INFO("y layer " << y << ": binned " << want << ", kernel " << got);
    CHECK(want > 0.45);  // a packed bed, its wall layers too
    CHECK(got == Approx(want).margin(0.04));
  }
  for (int x = 0; x < g.nx(); ++x) {
    const auto layer = [&](int xx, int, int z) { return xx == x && in_bed(z); };
    const double want = mean_over(g, binned, {}, layer), got = mean_over(g, phi, {}, layer);
    INFO("x layer " << x << ": binned " << want << ", kernel " << got);
    CHECK(want > 0.45);  // a packed bed, its wall layers too
    CHECK(got == Approx(want).margin(0.04));
  }
  for (int z = 0; z < 2; ++z) {  // the floor layer (1.2 cells of the box) and the next
    const auto layer = [&](int, int, int zz) { return zz == z; };
    const double want = mean_over(g, binned, {}, layer), got = mean_over(g, phi, {}, layer);
    INFO("z layer " << z << ": binned " << want << ", kernel " << got);
    CHECK(want > 0.45);  // a packed bed, its wall layers too
    CHECK(got == Approx(want).margin(0.04));
  }
  // The kernel without the box (fluid mask 1, the deposit over dx^3) reads the y walls and the
  // floor, where the outer cells hold 1.2 cells of the box, 0.05-0.10 above the binned fraction
  // (measured 0.048, 0.054, 0.103): the checks above tell the two apart there. At the x walls
  // (0.8 of a cell) it reads within 0.03 of the binned one, as the box's kernel does: the beads'
  // ordering against the wall thins the 1.6 mm layer by as much as the plain kernel's dilution
  // by a, here. The uniform bed above separates the two at such walls as well.
  ParticleKernel plain(g, f, default_kernel_width(dx, 2 * r));
  plain.locate(bed.x);
  plain.gas_fraction(bed.r, kDefaultEpsMin, eps);
  for (std::size_t c = 0; c < eps.size(); ++c) phi[c] = 1 - eps[c];
  const auto off = [&](auto layer) {
    return std::abs(mean_over(g, phi, {}, layer) - mean_over(g, binned, {}, layer));
  };
  CHECK(off([&](int, int y, int z) { return y == 0 && in_bed(z); }) > 0.04);
  CHECK(off([&](int, int y, int z) { return y == g.ny() - 1 && in_bed(z); }) > 0.04);
  CHECK(off([&](int, int, int z) { return z == 0; }) > 0.04);
}

TEST_CASE("Kernel walls: mirrored particles deposit a mirrored field", "[coupling]") {
  // The Mueller bed's coarse-grained runs all leaned the same way (particles rising along x_lo):
  // a kernel whose reflection or balancing at x_lo differed from x_hi would be a cause. Particles
  // and their images in the plane x = the box's middle deposit a field even in x, and
  // interpolation of an even field reads the same at a particle and its image, to round-off (the
  // two sides sum in other orders). Grid and kernel as the l = 2 case: 22 x 5 cells of 2 mm,
  // sigma 2.4 cells, walls on every face.
  const double dx = 2e-3;
  const LatticeFrame f{Vec3(0.5 * dx, 0.5 * dx, 0.5 * dx), dx};
  const Grid g(22, 5, 12, {false, false, false});
  ParticleKernel k(g, f, 2.4 * dx);
  const double mid = f.to_si(Vec3(0.5 * (g.nx() - 1), 0, 0)).x();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> x;
  for (int p = 0; p < 200; ++p) {
    const Vec3 a(u(rng) * g.nx() * dx, u(rng) * g.ny() * dx, u(rng) * g.nz() * dx);
    x.push_back(a);
    x.push_back(Vec3(2 * mid - a.x(), a.y(), a.z()));
  }
  k.locate(x);
  std::vector<double> q(x.size());
  for (std::size_t p = 0; p < q.size(); p += 2) q[p] = q[p + 1] = 1e-9 * (1 + u(rng));
  std::vector<double> phi;
  k.deposit(q, phi);
  double diff = 0, top = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int i = 0; i < g.nx(); ++i) {
        const double a = phi[std::size_t(g.compact_index(i, y, z))];
        const double b = phi[std::size_t(g.compact_index(g.nx() - 1 - i, y, z))];
        diff = std::max(diff, std::abs(a - b)), top = std::max(top, std::abs(a));
      }
  CAPTURE(diff, top);
  CHECK(diff <= 1e-13 * top);
  std::vector<double> field(std::size_t(g.cells())), at;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int i = 0; i < g.nx(); ++i) {
        const double m = i - 0.5 * (g.nx() - 1);
        field[std::size_t(g.compact_index(i, y, z))] = std::cos(0.3 * m) + 0.1 * y * z;
      }
  k.interpolate(field, at);
  double idiff = 0;
  for (std::size_t p = 0; p < at.size(); p += 2)
    idiff = std::max(idiff, std::abs(at[p] - at[p + 1]));
  CAPTURE(idiff);
  CHECK(idiff <= 1e-13);
}

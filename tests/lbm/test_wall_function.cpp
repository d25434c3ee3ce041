// The wall function (lbm/boundary/wall_function.hpp): the closed form against the power-law
// profile it integrates, the links' imposed stress against the law, the laminar limit against the
// Poiseuille parabola, and conservation on a staircase wall.
#include <omp.h>

#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>
#include <cstring>
#include <vector>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

constexpr double kA = 8.3, kB = 1.0 / 7.0;

// Werner & Wengle's profile u / u_tau against y+ (linear, then the 1/7 power law), averaged over a
// cell of height dz by composite Simpson quadrature: independent of the closed form under test.
double cell_mean_speed(double u_tau, double nu, double dz) {
  const int n = 200000;
  const double h = dz / n;
  auto u = [&](double y) {
    const double yp = y * u_tau / nu;
    return u_tau * (yp <= std::pow(kA, 1.0 / (1.0 - kB)) ? yp : kA * std::pow(yp, kB));
  };
  double s = u(0) + u(dz);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * u(i * h);
  return s * h / 3.0 / dz;
}

// u_tau whose profile has cell mean u, by bisection.
double friction_velocity(double u, double nu, double dz) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cell_mean_speed(mid, nu, dz) < u ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("Werner-Wengle closed form is the cell mean of the power-law profile", "[lbm]") {
  // Quadrature error of Simpson with 2e5 intervals, the kink at y+ = 11.81 included: below 1e-9;
  // the bisection ends at 1e-18. The 1e-7 bound is theirs with margin.
  const WernerWengle law{1.5e-5};
  for (const double dz : {5e-4, 2e-3})
    for (const double u : {1e-3, 0.1, 1.0, 30.0, 120.0}) {
      const double u_tau = std::sqrt(law.kinematic_stress(u, dz));
      CHECK(cell_mean_speed(u_tau, law.nu, dz) == Approx(u).epsilon(1e-7));
    }
  // The laminar branch is the no-slip gradient across half a cell.
  CHECK(law.kinematic_stress(1e-3, 5e-4) == Approx(2.0 * 1.5e-5 * 1e-3 / 5e-4).epsilon(1e-14));
}

TEST_CASE("wall-function links give the wall exactly the law's stress and no mass", "[lbm]") {
  // Uniform flow over a z_lo wall: after one step each wall cell still has its initial momentum
  // (the collision conserves it, no force), so the wall must receive, per unit area, the stress
  // of the law at that speed, along the flow. Reference: the quadrature above (1e-7).
  LbmSettings s;
  s.nx = 4;
  s.ny = 3;
  s.nz = 5;
  s.faces[4].kind = s.faces[5].kind = FaceKind::wall;
  const double nu = 2e-4;
  s.collision = RegularizedLes::from_tau(0.5 + 3.0 * nu, 0.1);
  LbmSolver lbm(s);
  const int wall = lbm.face_body(4);
  lbm.set_wall_function(wall, true);
  lbm.set_wall_function(lbm.face_body(5), true);
  const Vec3 u0(0.05, -0.02, 0.0);
  lbm.initialize([&](int, int, int, double& rho, Vec3& u) {
    rho = 1.0;
    u = u0;
  });
  const double m0 = lbm.total_mass();
  lbm.step();
  const double speed = u0.norm();
  const double u_tau = friction_velocity(speed, nu, 1.0);
  const double cells = s.nx * s.ny;
  const Vec3 f = lbm.wall_force(wall);
  CHECK(f.x() == Approx(cells * u_tau * u_tau * u0.x() / speed).epsilon(1e-7));
  CHECK(f.y() == Approx(cells * u_tau * u_tau * u0.y() / speed).epsilon(1e-7));
  // In the log layer (y+ of the cell centre about 20), far below no slip's 2 nu u per cell.
  CHECK(u_tau * 0.5 / nu > 11.81);
  CHECK(std::abs(lbm.mass_flow(wall)) < 1e-15);
  CHECK(lbm.total_mass() == Approx(m0).epsilon(1e-15));
}

TEST_CASE("in the viscous sublayer the wall function keeps the Poiseuille parabola", "[lbm]") {
  // Linear branch: tau_w = 2 nu u_1, with u_1 the first cell's speed. The force balance fixes
  // tau_w = F H / 2, so u_1 = F H / (4 nu), while the parabola has F (H - 1/2) / (4 nu) at the
  // cell centre: the whole profile shifts by F / (8 nu), 1 / H^2 of the centre speed F H^2 / (8 nu)
  // (no slip read at the centre instead of the face). TRT at Lambda = 3/16 is exact for the
  // parabola itself, so the error must be that shift, to 5 % of it (the slow shear mode decays for
  // 30 e-folds, about 4,400 steps; the bound covers what is left).
  const int h = 12;
  const double nu = 0.1;
  const double u_c = 0.01;
  const double force = 8.0 * nu * u_c / (h * h);
  LbmSettings s;
  s.nx = 2;
  s.ny = 1;
  s.nz = h;
  s.faces[4].kind = s.faces[5].kind = FaceKind::wall;
  s.collision = Trt::from_tau(0.5 + 3.0 * nu);
  s.body_force = Vec3(force, 0, 0);
  LbmSolver lbm(s);
  lbm.set_wall_function(lbm.face_body(4), true);
  lbm.set_wall_function(lbm.face_body(5), true);
  lbm.initialize([&](int, int, int, double& rho, Vec3& u) {
    rho = 1.0;
    u = Vec3::Zero();
  });
  const long steps = long(30.0 / (nu * M_PI * M_PI / (h * h)));
  for (long k = 0; k < steps; ++k) lbm.step();
  // The first cell is in the sublayer: the law's linear branch applies.
  CHECK(force * h / (4 * nu) < 0.5 * nu * std::pow(kA, 2.0 / (1.0 - kB)));
  for (int z = 0; z < h; ++z) {
    const double zeta = z + 0.5;
    const double exact = force * zeta * (h - zeta) / (2.0 * nu);
    CHECK(lbm.moments(0, 0, z).ux - exact == Approx(force / (8.0 * nu)).epsilon(0.05));
  }
}

TEST_CASE("a swirl in a staircase cylinder with the wall function conserves mass and momentum",
          "[lbm]") {
  // A voxelized cylinder (radius 9 cells, periodic along z) holding a solid-body rotation at a
  // wall speed of 0.05: every staircase configuration of links. The wall function adds no mass
  // (n is the links' weighted mean direction, so the slip terms cancel; 1e-13 relative allows
  // round-off over the steps), the gas's momentum change is minus the wall's impulse to round-off,
  // and the swirl keeps more angular momentum than with no-slip walls, as the law's stress at
  // y+ ~ 30 is below the no-slip gradient's.
  auto run = [](bool wall_function) {
    LbmSettings s;
    s.nx = s.ny = 22;
    s.nz = 2;
    s.faces[0].kind = s.faces[1].kind = s.faces[2].kind = s.faces[3].kind = FaceKind::wall;
    const double nu = 2e-4;
    s.collision = RegularizedLes::from_tau(0.5 + 3.0 * nu, 0.1);
    LbmSolver lbm(s);
    const int wall = lbm.add_body("cylinder");
    const double c = 10.5, r = 9.0, omega = 0.05 / r;
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x)
          if (std::hypot(x - c, y - c) > r) lbm.set_cell(x, y, z, wall);
    if (wall_function) lbm.set_wall_function(wall, true);
    lbm.initialize([&](int x, int y, int, double& rho, Vec3& u) {
      rho = 1.0;
      u = Vec3(-omega * (y - c), omega * (x - c), 0);
    });
    const double m0 = lbm.total_mass();
    const Vec3 p0 = lbm.raw_momentum();
    Vec3 impulse = Vec3::Zero();
    for (int k = 0; k < 400; ++k) {
      lbm.step();
      for (int b = 1; b <= lbm.body_count(); ++b) impulse += lbm.wall_force(b);
    }
    CHECK(lbm.total_mass() == Approx(m0).epsilon(1e-13));
    CHECK((lbm.raw_momentum() - p0 + impulse).norm() < 1e-12 * m0);
    double l = 0;
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x) {
        if (std::hypot(x - c, y - c) > r) continue;
        const CellMoments m = lbm.moments(x, y, 0);
        l += m.rho * ((x - c) * m.uy - (y - c) * m.ux);
      }
    return l;
  };
  const double l_wf = run(true), l_ns = run(false);
  INFO("angular momentum after 400 steps: wall function " << l_wf << ", no slip " << l_ns);
  CHECK(l_wf > l_ns);
}

TEST_CASE("the wall function is bitwise the same at 1 and 2 threads over several summation blocks",
          "[lbm]") {
  // Equivalence, not validation: a 66 x 64 floor has 4,224 wall cells, 16 summation blocks of
  // 264 cells (wall_function.cpp), so both threads apply cells, most of them in flat runs
  // (rows split where the periodic x edge wraps a link).
  auto run = [](int threads) {
    omp_set_num_threads(threads);
    LbmSettings s;
    s.nx = 66;
    s.ny = 64;
    s.nz = 3;
    s.faces[4].kind = s.faces[5].kind = FaceKind::wall;
    s.collision = RegularizedLes::from_tau(0.5 + 3.0 * 2e-4, 0.12);
    s.body_force = Vec3(2e-6, 1e-6, 0);
    LbmSolver lbm(s);
    lbm.set_wall_function(lbm.face_body(4), true);
    lbm.initialize([](int x, int y, int z, double& rho, Vec3& u) {
      rho = 1.0 + 0.01 * std::sin(0.3 * x + 0.2 * y);
      u = Vec3(0.04 + 0.01 * std::cos(0.4 * y), 0.01 * std::sin(0.5 * x), 0.002 * z);
    });
    for (int t = 0; t < 20; ++t) lbm.step();
    std::vector<double> out = lbm.stored_slots();
    const Vec3 f = lbm.wall_force(lbm.face_body(4));
    out.insert(out.end(), {f.x(), f.y(), f.z()});
    return out;
  };
  const std::vector<double> one = run(1), two = run(2);
  omp_set_num_threads(1);
  REQUIRE(one.size() == two.size());
  CHECK(std::memcmp(one.data(), two.data(), one.size() * sizeof(double)) == 0);
}

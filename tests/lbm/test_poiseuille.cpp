// Body-force-driven Poiseuille flow between two half-way bounce-back plates (z walls), periodic in
// x and y, against the parabola u(zeta) = F zeta (H - zeta) / (2 rho nu), zeta = z + 1/2, H = nz.
#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

struct Result {
  double max_error;  // max |u - u_exact| / u_centre over the channel
  double u_centre;
  double max_uz = 0;
};

Result poiseuille(const CollisionModel& op, int h, Precision storage = Precision::float64) {
  const double nu = viscosity(op);
  const double u_c = 0.01;                        // centre velocity, Mach 0.017
  const double force = 8.0 * nu * u_c / (h * h);  // u_c = F H^2 / (8 rho nu)
  LbmSettings s;
  s.nx = 4;
  s.ny = 1;
  s.nz = h;
  s.faces[4].kind = s.faces[5].kind = FaceKind::wall;
  s.collision = op;
  s.body_force = Vec3(force, 0, 0);
  s.precision = storage;
  LbmSolver lbm(s);
  auto exact = [&](int z) {
    const double zeta = z + 0.5;
    return force * zeta * (h - zeta) / (2.0 * nu);
  };
  lbm.initialize([&](int, int, int z, double& rho, Vec3& u) {
    rho = 1.0;
    u = Vec3(exact(z), 0, 0);
  });
  // The slowest transient is the first shear mode, decaying as exp(-nu (pi/H)^2 t); 30 e-folds
  // take an O(1e-3) start-up error (the Guo half-force shift, BGK's slip) below 1e-15.
  const long steps = long(30.0 / (nu * M_PI * M_PI / (h * h)));
  for (long k = 0; k < steps; ++k) lbm.step();
  Result r{0.0, u_c, 0.0};
  for (int z = 0; z < h; ++z)
    for (int x = 0; x < s.nx; ++x) {
      const CellMoments m = lbm.moments(x, 0, z);
      r.max_error = std::max(r.max_error, std::abs(m.ux - exact(z)) / u_c);
      r.max_uz = std::max(r.max_uz, std::abs(m.uz));
    }
  return r;
}

}  // namespace

TEST_CASE("TRT (Lambda = 3/16) with Guo forcing gives the exact Poiseuille parabola", "[lbm]") {
  // Exact: for Lambda = 3/16 the half-way bounce-back wall sits exactly half-way and the steady
  // parabola solves the discrete equations (Ginzburg & d'Humieres 2003, Phys. Rev. E 68, 066614),
  // so only round-off remains: 1e-10 leaves 5 orders for it on a 16-cell channel.
  for (double tau : {0.6, 1.0, 2.0}) {
    const Result r = poiseuille(Trt::from_tau(tau), 16);
    INFO("tau = " << tau);
    CHECK(r.max_error < 1e-10);
  }
}

TEST_CASE("Float populations keep the exact Poiseuille parabola to float round-off", "[lbm]") {
  // The same exact discrete solution with the populations stored as f - w in float
  // (lbm/pdf_field.hpp). Each step rounds every stored deviation to 2^-24 of itself; at u_c = 0.01
  // the deviations are about w (3 u + Dp) <= 0.04 w, so a step moves u by at most
  // 6e-8 * 0.04 * sum_q w_q |c_qx| (= 1/3) = 8e-10, 8e-8 of u_c. The steady state forgets errors
  // at the slowest shear mode's rate nu (pi/H)^2 = 1.3e-3 per step (tau = 0.6, H = 16), so even
  // rounding that always went one way settles below 6e-5 of u_c (1.3e-5 at tau = 1); u_z has no
  // source but the same rounding. Bound 1e-4: above that worst case. Measured 1.1e-5 (tau = 0.6)
  // and 2.7e-6 (tau = 1); without the w shift 4.2e-4 and 7.6e-5, which fails at tau = 0.6.
  for (double tau : {0.6, 1.0}) {
    const Result r = poiseuille(Trt::from_tau(tau), 16, Precision::float32);
    INFO("tau = " << tau << ", largest error " << r.max_error << " of u_c");
    CHECK(r.max_error < 1e-4);
    CHECK(r.max_uz < 1e-4 * r.u_centre);
  }
}

TEST_CASE("BGK (tau = 1) Poiseuille error is second order in the channel width", "[lbm]") {
  // With BGK the wall position error depends on tau (Lambda = (tau - 1/2)^2 = 1/4, not 3/16),
  // which shifts the profile by a slip u_s/u_c = O(1/H^2) (He, Zou, Luo & Dembo 1997, J. Stat.
  // Phys. 87, 115): the error falls 4x per doubling of H; the issue asks < 1 % at H = 32.
  const Bgk bgk = Bgk::from_tau(1.0);
  const double e8 = poiseuille(bgk, 8).max_error;
  const double e16 = poiseuille(bgk, 16).max_error;
  const double e32 = poiseuille(bgk, 32).max_error;
  INFO("errors " << e8 << " " << e16 << " " << e32);
  CHECK(e32 < 0.01);
  const double order1 = std::log2(e8 / e16), order2 = std::log2(e16 / e32);
  INFO("orders " << order1 << " " << order2);
  CHECK(order1 > 1.8);
  CHECK(order1 < 2.2);
  CHECK(order2 > 1.8);
  CHECK(order2 < 2.2);
}

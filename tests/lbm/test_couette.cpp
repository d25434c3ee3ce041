// Couette flow: the top plate (z_hi) moves with u_w along x, the bottom plate rests, periodic in x
// and y. Steady state u(zeta) = u_w zeta / H (zeta = z + 1/2, H = nz) and a wall shear stress
// rho nu u_w / H on each plate. In double (the reference) and in single precision (float
// populations f - w and float collision arithmetic, lbm/cell.hpp).
#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

constexpr int kNx = 8, kNy = 4, kH = 16;
constexpr double kUw = 0.02;

struct CouetteResult {
  double profile_error;  // max over cells of |u_x - u_w zeta / H| / u_w + (|u_y| + |u_z|) / u_w
  Vec3 top, bottom;      // momentum-exchange force on the plates
  double f_exact;        // rho nu u_w / H times the plate area
};

CouetteResult couette(const CollisionModel& op, Precision precision) {
  LbmSettings s;
  s.nx = kNx;
  s.ny = kNy;
  s.nz = kH;
  s.faces[4].kind = FaceKind::wall;
  s.faces[5].kind = FaceKind::wall;
  s.faces[5].wall_velocity = Vec3(kUw, 0, 0);
  s.collision = op;
  s.precision = precision;
  LbmSolver lbm(s);
  const double nu = viscosity(op);
  // Start at rest; the slowest shear mode decays as exp(-nu (pi/H)^2 t): 35 e-folds bring the
  // start-up transient (O(u_w)) below 1e-15 u_w.
  const long steps = long(35.0 / (nu * M_PI * M_PI / (kH * kH)));
  for (long k = 0; k < steps; ++k) lbm.step();
  CouetteResult r{0, Vec3::Zero(), Vec3::Zero(), 1.0 * nu * kUw / kH * kNx * kNy};
  for (int z = 0; z < kH; ++z)
    for (int y = 0; y < kNy; ++y)
      for (int x = 0; x < kNx; ++x) {
        const CellMoments m = lbm.moments(x, y, z);
        r.profile_error = std::max(r.profile_error, std::abs(m.ux - kUw * (z + 0.5) / kH) / kUw);
        r.profile_error = std::max(r.profile_error, std::abs(m.uy) / kUw + std::abs(m.uz) / kUw);
      }
  r.top = lbm.wall_force(lbm.face_body(5));
  r.bottom = lbm.wall_force(lbm.face_body(4));
  return r;
}

const char* name_of(const CollisionModel& op) {
  return std::visit([](const auto& o) { return o.name.data(); }, op);
}

}  // namespace

TEST_CASE("Couette flow: linear profile and momentum-exchange wall force", "[lbm]") {
  for (const CollisionModel& op :
       {CollisionModel(Bgk::from_tau(0.8)), CollisionModel(Trt::from_tau(0.8))}) {
    const CouetteResult r = couette(op, Precision::float64);
    // The linear profile has no curvature, so half-way bounce-back with Ladd's term is exact for
    // any tau (He et al. 1997, J. Stat. Phys. 87, 115): only round-off and the decayed transient
    // remain; 1e-10 of u_w leaves orders of margin for both.
    INFO("collision " << name_of(op));
    CHECK(r.profile_error < 1e-10);
    // Wall force = shear stress x plate area; the fluid drags the moving plate back (-x) and the
    // resting one forward. The issue asks for 1 % (waLBerla's BoundaryForceCouette uses 1 %), but
    // the momentum exchange is exact for tangential wall motion on flat walls at steady state, so
    // a 1 % bound would pass a wrong factor in the exchange's sum as long as it was small. 1e-10,
    // as for the profile: only round-off and the decayed transient remain (measured 9e-16 for
    // BGK, 9e-13 for TRT).
    INFO("top " << r.top.transpose() << " bottom " << r.bottom.transpose() << " exact " << r.f_exact
                << "; relative errors " << r.top.x() / -r.f_exact - 1 << ", "
                << r.bottom.x() / r.f_exact - 1);
    CHECK(r.top.x() == Approx(-r.f_exact).epsilon(1e-10));
    CHECK(r.bottom.x() == Approx(r.f_exact).epsilon(1e-10));
    CHECK(std::abs(r.top.y()) < 1e-12 * r.f_exact);
  }
}

TEST_CASE("Couette flow in single precision: linear profile and wall force to float round-off",
          "[lbm]") {
  // The same exact discrete solution, in float on f - w. Only float round-off is left, so the
  // bounds follow from it. The stored deviations f - w are at most about 3 w u_w = 0.06 w; each
  // step rounds each of them (and the float collision's few operations on them) to a few 2^-24 of
  // itself, which moves u by at most ~ 4 x 6e-8 x 0.06 x sum_q w_q |c_qx| (= 1/3) = 5e-10, 2.4e-8
  // of u_w. The profile forgets errors at the slowest shear mode's rate nu (pi/H)^2 = 3.9e-3 per
  // step (tau = 0.8, H = 16), so rounding that always went one way would settle at 6e-6 of u_w:
  // bound 5e-5 of u_w for the profile (and for u_y, u_z, which have no source but round-off).
  // Wall force: the plate's 32 cells x 5 links each carry a momentum 2 f_q c_qx whose stored part
  // is off by the settled profile error (6e-6 of u_w relative to the stress) plus one rounding of
  // f - w (6e-8 x 0.06 w), summed: 32 x 5 x 2 x 3.6e-9 w <= 6e-8 absolute against f_exact =
  // 4e-3, 1.5e-5 relative; the stress itself, nu du/dz, carries the profile's error over one
  // cell, 2 x 6e-6 / (1/16) = 2e-4 of it in the worst case. Bound 5e-4 relative, still 20 times
  // below the 1 % and far below a wrong factor in the exchange. The y force: 1e-4 of
  // f_exact (u_y's settled round-off, no source). Measured: profile 3.3e-6 (BGK) and 3.6e-7
  // (TRT) of u_w, plate forces within 1.9e-5 (BGK) and 7.4e-7 (TRT) of f_exact.
  for (const CollisionModel& op :
       {CollisionModel(Bgk::from_tau(0.8)), CollisionModel(Trt::from_tau(0.8))}) {
    const CouetteResult r = couette(op, Precision::float32);
    INFO("collision " << name_of(op) << " profile error / u_w " << r.profile_error);
    CHECK(r.profile_error < 5e-5);
    INFO("top " << r.top.transpose() << " bottom " << r.bottom.transpose() << " exact " << r.f_exact
                << "; relative errors " << r.top.x() / -r.f_exact - 1 << ", "
                << r.bottom.x() / r.f_exact - 1);
    CHECK(r.top.x() == Approx(-r.f_exact).epsilon(5e-4));
    CHECK(r.bottom.x() == Approx(r.f_exact).epsilon(5e-4));
    CHECK(std::abs(r.top.y()) < 1e-4 * r.f_exact);
  }
}

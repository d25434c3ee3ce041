// Couette flow: the top plate (z_hi) moves with u_w along x, the bottom plate rests, periodic in x
// and y. Steady state u(zeta) = u_w zeta / H (zeta = z + 1/2, H = nz) and a wall shear stress
// rho nu u_w / H on each plate.
#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>

using namespace lbdem;
using namespace lbdem::lbm;

TEST_CASE("Couette flow: linear profile and momentum-exchange wall force", "[lbm]") {
  const int nx = 8, ny = 4, h = 16;
  const double u_w = 0.02;
  for (const CollisionModel& op :
       {CollisionModel(Bgk::from_tau(0.8)), CollisionModel(Trt::from_tau(0.8))}) {
    LbmSettings s;
    s.nx = nx;
    s.ny = ny;
    s.nz = h;
    s.faces[4].kind = FaceKind::wall;
    s.faces[5].kind = FaceKind::wall;
    s.faces[5].wall_velocity = Vec3(u_w, 0, 0);
    s.collision = op;
    LbmSolver lbm(s);
    const double nu = viscosity(op);
    // Start at rest; the slowest shear mode decays as exp(-nu (pi/H)^2 t): 35 e-folds bring the
    // start-up transient (O(u_w)) below 1e-15 u_w.
    const long steps = long(35.0 / (nu * M_PI * M_PI / (h * h)));
    for (long k = 0; k < steps; ++k) lbm.step();
    // The linear profile has no curvature, so half-way bounce-back with Ladd's term is exact for
    // any tau (He et al. 1997, J. Stat. Phys. 87, 115): only round-off and the decayed transient
    // remain; 1e-10 of u_w leaves orders of margin for both.
    double err = 0;
    for (int z = 0; z < h; ++z)
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
          const CellMoments m = lbm.moments(x, y, z);
          err = std::max(err, std::abs(m.ux - u_w * (z + 0.5) / h) / u_w);
          err = std::max(err, std::abs(m.uy) / u_w + std::abs(m.uz) / u_w);
        }
    INFO("collision " << std::visit([](const auto& o) { return o.name; }, op));
    CHECK(err < 1e-10);
    // Wall force = shear stress x plate area; the fluid drags the moving plate back (-x) and the
    // resting one forward. The issue asks for 1 % (waLBerla's BoundaryForceCouette uses 1 %), but
    // the momentum exchange is exact for tangential wall motion on flat walls at steady state, so
    // a 1 % bound would pass a wrong factor in the exchange's sum as long as it was small. 1e-10,
    // as for the profile: only round-off and the decayed transient remain (measured 9e-16 for
    // BGK, 9e-13 for TRT).
    const double f_exact = 1.0 * nu * u_w / h * nx * ny;
    const Vec3 top = lbm.wall_force(lbm.face_body(5));
    const Vec3 bottom = lbm.wall_force(lbm.face_body(4));
    INFO("top " << top.transpose() << " bottom " << bottom.transpose() << " exact " << f_exact
                << "; relative errors " << top.x() / -f_exact - 1 << ", "
                << bottom.x() / f_exact - 1);
    CHECK(top.x() == Approx(-f_exact).epsilon(1e-10));
    CHECK(bottom.x() == Approx(f_exact).epsilon(1e-10));
    CHECK(std::abs(top.y()) < 1e-12 * f_exact);
  }
}

// Free fall: velocity Verlet integrates a constant force exactly, so x(t) = x0 + v0 t + g t^2/2
// holds to round-off.
#include <catch2/catch.hpp>

#include "helpers/dem_setup.hpp"

using namespace lbdem;

TEST_CASE("free fall is exact to round-off", "[dem][physics]") {
  const Vec3 g(0.3, -0.2, -9.81), x0(0.001, 0.002, 0.04), v0(0.1, 0.05, 0.2);
  auto s = test::settings(1e-5, g);
  s.domain.lo = Vec3(-0.01, -0.01, 0.0);
  s.domain.hi = Vec3(0.01, 0.01, 0.06);
  dem::DemSolver sol(s, {test::glass()});
  sol.add_particle(x0, v0, 5e-4, 0);
  const int n = 5000;
  for (int k = 0; k < n; ++k) sol.step();
  REQUIRE(sol.particles().size() == 1);  // stayed in the domain
  const double t = n * s.dt;
  const Vec3 x = x0 + v0 * t + 0.5 * g * t * t, v = v0 + g * t;
  // Round-off only: 5000 steps of additions of O(1e-2) m accumulate ~1e-13 relative error.
  CHECK((sol.particles().x[0] - x).norm() < 1e-12 * x.norm());
  CHECK((sol.particles().v[0] - v).norm() < 1e-12 * v.norm());
  CHECK(sol.time() == Approx(t).epsilon(1e-15));
}

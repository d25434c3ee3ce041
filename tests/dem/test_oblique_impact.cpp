// Oblique sphere-wall impact in gross sliding: with J the impulse of the compressive normal force
// and the friction force mu max(F_n, 0) throughout, the rebound tangential velocity is v_t - mu J/m
// and the spin 5 mu J / (2 m R) (Maw, Barber & Fawcett 1976; Thornton 1997 regime of full sliding).
#include <catch2/catch.hpp>
#include <cmath>

#include "helpers/dem_setup.hpp"

using namespace lbdem;

TEST_CASE("oblique impact in gross sliding: tangential velocity and spin from the normal impulse",
          "[dem][physics]") {
  const double r = 5e-4, mu = 0.2, e = 0.5;
  for (const std::string law : {"hertz_mindlin", "linear"}) {
    auto mat = test::glass(e, mu);
    mat.youngs_modulus = 1e9;  // stiff: the overlap stays < 0.5 % of R, so the torque arm is ~R
    mat.stiffness = 1e5;
    dem::ContactSettings cs;
    cs.normal = law;
    auto s = test::settings(5e-8);
    s.contact = cs;
    dem::DemSolver sol(s, {mat});
    sol.add_wall(test::floor_wall(0));
    // tan(incidence from the normal) = 3 / 0.5 = 6 > 3.5 mu (1 + e) = 1.05: sliding throughout.
    const Vec3 v_in(3.0, 0, -0.5);
    sol.add_particle(Vec3(0, 0, r + 1e-7), v_in, r, 0);
    const double m = sol.particles().mass[0];
    double J = 0;
    bool seen = false;
    for (int k = 0; k < 1000000; ++k) {
      sol.step();
      const double fn =
          -sol.walls()[0].force.z();  // normal force on the particle (floor normal +z)
      J += std::max(fn, 0.0) * s.dt;  // velocity Verlet applies sum F dt exactly
      if (sol.contacts_pw()) seen = true;
      if (seen && !sol.contacts_pw()) break;
    }
    const auto& p = sol.particles();
    INFO(law << ": J = " << J);
    REQUIRE(J > 0);
    // 1 %: the friction force follows the cap at every step (checked: spring above the cap from
    // the second step on); the arm R - delta differs from R by < 0.5 %.
    CHECK(p.v[0].x() == Approx(v_in.x() - mu * J / m).epsilon(0.01));
    CHECK(p.omega[0].y() == Approx(5 * mu * J / (2 * m * r)).epsilon(0.01));
  }
}

// The watchdog folded into the DEM step (DemSolver::alarm): the first particle (lowest index) that
// is faster than the limit or has a non-finite state raises it at the step that finds it, the step
// ends there, and a sound run never raises it.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "helpers/dem_setup.hpp"

using namespace lbdem;

TEST_CASE("the DEM watchdog names the first particle past the speed limit", "[dem][watchdog]") {
  dem::DemSolver sol(test::settings(1e-5), {test::glass()});
  sol.add_particle(Vec3(-0.005, 0, 0), Vec3(0.5, 0, 0), 5e-4, 0);
  sol.add_particle(Vec3(0, 0, 0), Vec3(0, 3, 0), 5e-4, 0);
  sol.add_particle(Vec3(0.005, 0, 0), Vec3(0, 0, -4), 5e-4, 0);
  sol.set_speed_limit(2.0);
  sol.step();
  REQUIRE(sol.alarm());
  const dem::DemAlarm& a = *sol.alarm();
  CHECK(a.id == 1);  // the lowest index of the two too fast
  CHECK(a.finite);
  CHECK(a.step == 1);
  CHECK(a.v.norm() == Approx(3.0));
  CHECK(a.x.y() == Approx(3e-5));  // after the step's drift
}

TEST_CASE("the DEM watchdog catches a non-finite force, and is silent on a sound run",
          "[dem][watchdog]") {
  dem::DemSolver sol(test::settings(1e-5, Vec3(0, 0, -9.81)), {test::glass()});
  sol.add_wall(test::floor_wall(-0.005));
  sol.add_particle(Vec3(0, 0, -0.0045), Vec3(0, 0, -0.2), 5e-4, 0);
  sol.add_particle(Vec3(0.002, 0, 0), Vec3::Zero(), 5e-4, 0);
  // A bounce on the floor under a limit above every speed reached: no alarm.
  sol.set_speed_limit(1.0);
  for (int k = 0; k < 2000; ++k) sol.step();
  CHECK_FALSE(sol.alarm());
  // A NaN force (a coupling gone wrong) is found in the next step, with the particle's id.
  const std::int64_t id = sol.particles().id[1];
  sol.particles().external[1] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  sol.step();  // the force turns NaN here
  sol.step();  // and the half kick meets it
  REQUIRE(sol.alarm());
  CHECK(sol.alarm()->id == id);
  CHECK_FALSE(sol.alarm()->finite);
  CHECK(std::isnan(sol.alarm()->force.x()));
  CHECK(sol.alarm()->step == 2002);
}

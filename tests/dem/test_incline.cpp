// A sphere on an incline (gravity tilted by theta against a floor): it rolls without slip, with
// a = 5/7 g sin(theta), while tan(theta) < 3.5 mu, and slides with a = g (sin(theta) - mu
// cos(theta)) above (solid sphere, I = 2/5 m R^2).
#include <catch2/catch.hpp>
#include <cmath>

#include "helpers/dem_setup.hpp"

using namespace lbdem;

namespace {
// Acceleration along the slope measured between t0 and t1, after the contact has settled.
double slope_acceleration(double theta, double mu, const std::string& law) {
  const double r = 5e-4, g = 9.81;
  auto mat = test::glass(0.5, mu);
  mat.youngs_modulus = 1e8;
  dem::ContactSettings cs;
  cs.normal = law;
  auto s = test::settings(2e-7, Vec3(g * std::sin(theta), 0, -g * std::cos(theta)));
  s.contact = cs;
  s.domain.lo = Vec3(-0.005, -0.005, -0.005);  // it travels < 4 mm
  s.domain.hi = Vec3(0.02, 0.005, 0.01);
  dem::DemSolver sol(s, {mat});
  sol.add_wall(test::floor_wall(0));
  // Touching the floor at zero overlap: it sinks to the static overlap of its weight (0.04 um for
  // Hertz at E = 1e8 Pa) and the small bounce that starts is damped (e = 0.5) in the 4 ms of
  // settling before the acceleration is measured.
  sol.add_particle(Vec3(0, 0, r), Vec3::Zero(), r, 0);
  const int settle = 20000, measure = 100000;  // 4 ms and 20 ms
  for (int k = 0; k < settle; ++k) sol.step();
  const double v0 = sol.particles().v[0].x();
  for (int k = 0; k < measure; ++k) sol.step();
  return (sol.particles().v[0].x() - v0) / (measure * s.dt);
}
}  // namespace

TEST_CASE("sphere on an incline rolls below tan(theta) = 3.5 mu and slides above",
          "[dem][physics]") {
  const double g = 9.81, mu = 0.2;
  for (const std::string law : {"hertz_mindlin", "linear"}) {
    INFO(law);
    // Rolling: tan(theta) = 0.35 < 3.5 mu = 0.7. 1 %: the tangential spring's oscillation after the
    // start has decayed (tangential damping) well within the 4 ms settling time.
    const double th_roll = std::atan(0.35);
    CHECK(slope_acceleration(th_roll, mu, law) ==
          Approx(5.0 / 7.0 * g * std::sin(th_roll)).epsilon(0.01));
    // Sliding: tan(theta) = 1.0 > 0.7.
    const double th_slide = std::atan(1.0);
    CHECK(slope_acceleration(th_slide, mu, law) ==
          Approx(g * (std::sin(th_slide) - mu * std::cos(th_slide))).epsilon(0.01));
  }
}

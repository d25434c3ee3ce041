// Van der Waals cohesion against the Hamaker sphere-sphere formula F = A R* / (6 h^2).
#include <catch2/catch.hpp>

#include "dem/contact/van_der_waals.hpp"
#include "helpers/dem_setup.hpp"

using namespace lbdem;

TEST_CASE("van der Waals force follows A R*/(6 h^2), clamped at h_min and cut at h_max",
          "[dem][physics][cohesion]") {
  const dem::VanDerWaals::Params p{1e-19, 4e-10, 1e-5};
  const double r_star = 25e-6;  // two 100 um spheres
  // The fluidized-bed study's reference: 2.6 uN at h = h_min = 0.4 nm (A d / (24 h^2) with d = 100
  // um).
  CHECK(dem::VanDerWaals::eval(p, -4e-10, r_star).f ==
        Approx(1e-19 * 100e-6 / (24 * 16e-20)).epsilon(1e-12));
  CHECK(dem::VanDerWaals::eval(p, -4e-10, r_star).f == Approx(2.6e-6).epsilon(0.01));
  for (double h : {1e-9, 1e-8, 1e-7, 1e-6})
    CHECK(dem::VanDerWaals::eval(p, -h, r_star).f ==
          Approx(1e-19 * r_star / (6 * h * h)).epsilon(1e-12));
  CHECK(dem::VanDerWaals::eval(p, 1e-6, r_star).f ==
        Approx(1e-19 * r_star / (6 * 16e-20)).epsilon(1e-12));  // in contact: h = h_min
  CHECK(dem::VanDerWaals::eval(p, -2e-5, r_star).f == 0.0);     // beyond h_max
}

TEST_CASE("van der Waals pull between two particles in the solver", "[dem][physics][cohesion]") {
  const double r = 50e-6, h = 2e-8;
  auto mat = test::glass();
  mat.hamaker = 1e-19;
  dem::ContactSettings cs;
  cs.cohesion = "van_der_waals";
  cs.h_min = 4e-10;
  cs.h_max = 1e-5;
  auto s = test::settings(1e-9);
  s.contact = cs;
  s.skin = 1e-6;
  s.domain.lo = Vec3(-1e-3, -1e-3, -1e-3);
  s.domain.hi = Vec3(1e-3, 1e-3, 1e-3);
  dem::DemSolver sol(s, {mat});
  sol.add_particle(Vec3(-r - h / 2, 0, 0), Vec3::Zero(), r, 0);
  sol.add_particle(Vec3(r + h / 2, 0, 0), Vec3::Zero(), r, 0);
  sol.step();
  // After one step of 1 ns the gap has changed by ~1e-16 m: the force is the formula's to 1e-6.
  const double expected = 1e-19 * (r / 2) / (6 * h * h);
  CHECK(sol.particles().force[0].x() == Approx(expected).epsilon(1e-6));  // pulled towards +x
  CHECK(sol.particles().force[1].x() == Approx(-expected).epsilon(1e-6));
}

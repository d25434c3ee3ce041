// Pair mixing against the values bench/peers/README.md states for its case (E = 5 MPa,
// nu = 0.3: E* = E/(2(1-nu^2)) = 2.747e6 Pa, G* = E/(4(2-nu)(1+nu)) = 5.656e5 Pa) and a
// hand-computed unequal pair.
#include <catch2/catch.hpp>

#include "dem/material.hpp"

using namespace lbdem;

TEST_CASE("material pair mixing: E*, G*, stiffness, Hamaker", "[dem][material]") {
  dem::Material a;
  a.youngs_modulus = 5e6;
  a.poisson_ratio = 0.3;
  const auto same = dem::mix(a, a);
  // 4 significant digits as printed in the reference.
  CHECK(same.e_star == Approx(2.747e6).epsilon(2e-4));
  CHECK(same.g_star == Approx(5.656e5).epsilon(2e-4));
  CHECK(same.stiffness == Approx(a.stiffness));  // equal materials keep k
  dem::Material b = a;
  b.youngs_modulus = 2e7;
  b.poisson_ratio = 0.25;
  b.stiffness = 3000;
  b.hamaker = 4e-20;
  a.hamaker = 1e-20;
  const auto ab = dem::mix(a, b);
  // 1/E* = 0.91/5e6 + 0.9375/2e7; 1/G* = (2-0.3)/(5e6/2.6) + (2-0.25)/(2e7/2.5).
  CHECK(ab.e_star == Approx(1.0 / (0.91 / 5e6 + 0.9375 / 2e7)).epsilon(1e-12));
  CHECK(ab.g_star == Approx(1.0 / (1.7 / (5e6 / 2.6) + 1.75 / (2e7 / 2.5))).epsilon(1e-12));
  CHECK(ab.stiffness == Approx(2 * 1000.0 * 3000.0 / 4000.0).epsilon(1e-12));
  CHECK(ab.hamaker == Approx(2e-20).epsilon(1e-12));  // geometric mean
  CHECK(dem::effective(1e-3, 3e-3) == Approx(0.75e-3));
  CHECK(dem::effective(1e-3, 0) == 1e-3);  // a wall: R* = R
}

// Force-energy consistency of every elastic law: F = -dU/d(gap) by central differences
// (HOOMD's test_force_energy_relationship). rtol 1e-6: the central difference error is
// O(h^2 U''') with h = 1e-4 of the overlap.
#include <catch2/catch.hpp>

#include "dem/contact/hertz_mindlin.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/van_der_waals.hpp"

using namespace lbdem;

TEST_CASE("elastic force is minus the derivative of the stored energy", "[dem][physics]") {
  const double r_star = 2.5e-4;
  const dem::HertzMindlin::Params hm{2.7e6, 1e6, 0, 0};
  const dem::LinearSpringDashpot::Params ls{1000, 0, 2.0 / 7.0, 0, 0};
  for (double d : {1e-7, 1e-6, 1e-5}) {
    const double h = 1e-4 * d;
    const auto up = dem::HertzMindlin::elastic(hm, d + h, r_star),
               dn = dem::HertzMindlin::elastic(hm, d - h, r_star);
    CHECK(dem::HertzMindlin::elastic(hm, d, r_star).f_el ==
          Approx((up.u_el - dn.u_el) / (2 * h)).epsilon(1e-6));
    const auto lu = dem::LinearSpringDashpot::elastic(ls, d + h, r_star),
               ld = dem::LinearSpringDashpot::elastic(ls, d - h, r_star);
    CHECK(dem::LinearSpringDashpot::elastic(ls, d, r_star).f_el ==
          Approx((lu.u_el - ld.u_el) / (2 * h)).epsilon(1e-6));
  }
  // Van der Waals: attraction f = +dU/d(gap) (U rises as the gap opens), inside and outside h_min.
  const dem::VanDerWaals::Params p{1e-20, 4e-10, 1e-5};
  for (double gap : {1e-9, 1e-8, 1e-6, -1e-9}) {
    const double h = 1e-4 * std::abs(gap);
    const double du = (dem::VanDerWaals::eval(p, -(gap + h), r_star).u -
                       dem::VanDerWaals::eval(p, -(gap - h), r_star).u) /
                      (2 * h);
    CHECK(dem::VanDerWaals::eval(p, -gap, r_star).f == Approx(du).epsilon(1e-6));
  }
}

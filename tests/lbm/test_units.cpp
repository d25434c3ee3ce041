// SI <-> lattice conversions against their dimensional formulas and the fluidized bed's worked
// example, and the stability checks firing where they should.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "lbm/units.hpp"

using namespace lbdem;
using namespace lbdem::lbm;

TEST_CASE("Lattice units: conversions round-trip and follow their dimensions", "[lbm]") {
  const LatticeUnits u{3e-4, 2e-6, 1.2};
  // Round trips are exact up to two roundings.
  CHECK(u.velocity_to_si(u.velocity_to_lattice(0.357)) == Approx(0.357).epsilon(1e-15));
  // A force density f [N/m^3] on a cell of volume dx^3 is a force f dx^3 [N]: the two paths agree.
  const double f = 1234.5;
  CHECK(u.force_to_si(u.force_density_to_lattice(f)) ==
        Approx(f * std::pow(u.dx, 3)).epsilon(1e-14));
  // tau = 1/2 + 3 nu dt / dx^2 for air at these steps: nu = 1.5e-5 m^2/s.
  CHECK(u.viscosity_to_lattice(1.5e-5) == Approx(1.5e-5 * 2e-6 / 9e-8).epsilon(1e-14));
  // c_s = dx / (sqrt3 dt) = 86.6 m/s, and rho c_s^2 = 9000 Pa.
  CHECK(u.cs_si() == Approx(86.60254).epsilon(1e-6));
  CHECK(u.density_change(90.0) == Approx(0.01).epsilon(1e-12));
}

TEST_CASE("Lattice units: the fluidized bed's 88 Pa needs dt of about 2 us at dx = 0.3 mm",
          "[lbm]") {
  // docs/physics.md: Dp / (rho c_s^2) <= 1 % with Dp = 88 Pa, rho = 1.2, dx = 0.3 mm gives dt ~ 2
  // us; by hand 3 Dp dt^2 / (rho dx^2) = 0.01 gives dt = dx sqrt(0.01 * 1.2 / (3 * 88)) = 2.0226e-6
  // s.
  const double dt = max_dt_for_pressure(88.0, 1.2, 3e-4, 0.01);
  CHECK(dt == Approx(3e-4 * std::sqrt(0.01 * 1.2 / (3 * 88.0))).epsilon(1e-12));
  CHECK(dt == Approx(2.0226e-6).epsilon(1e-4));  // the hand figure, to its 5 digits
  CHECK(LatticeUnits{3e-4, dt, 1.2}.density_change(88.0) == Approx(0.01).epsilon(1e-12));
}

TEST_CASE("Stability checks: tau, Mach and static pressure errors name the key and the fix",
          "[lbm]") {
  StabilityInput in;
  in.units = {3e-4, 2e-6, 1.2};
  in.nu_si = 1.5e-5;  // air: tau - 1/2 = 3 nu dt / dx^2 = 1e-3, the fluidized bed's
  in.u_max_si = 1.0;
  in.dp_static_si = 88;
  const StabilityReport ok = check_stability(in);
  CHECK(ok.tau == Approx(0.501).epsilon(1e-12));
  CHECK(ok.warnings.empty());

  SECTION("tau too close to 1/2, unless the LES eddy viscosity lifts it") {
    in.units.dt = 2e-8;  // tau - 1/2 = 1e-5, below the default margin 1e-4
    CHECK_THROWS_WITH(check_stability(in), Catch::Contains("'fluid.dt'") &&
                                               Catch::Contains("of 1/2") &&
                                               Catch::Contains("fix:"));
    in.nu_turbulent_max_si = 1e-3;  // effective tau - 1/2 = 3 (1.015e-3) 2e-8 / 9e-8 = 6.767e-4
    CHECK(check_stability(in).tau_effective_max - 0.5 == Approx(6.7667e-4).epsilon(1e-4));
  }
  SECTION("lattice Mach: warning above 0.2, error above 0.3") {
    // Ma = (u dt / dx) sqrt3: u = 20 m/s gives 0.2309, u = 30 m/s 0.3464.
    in.u_max_si = 20;
    CHECK(check_stability(in).warnings.size() == 1);
    in.u_max_si = 30;
    CHECK_THROWS_WITH(check_stability(in), Catch::Contains("Mach") && Catch::Contains("fix:"));
  }
  SECTION("static pressure: warning above 1 %, error above 3 % of rho c_s^2") {
    in.dp_static_si = 180;  // 2 % of 9000 Pa
    CHECK(check_stability(in).warnings.size() == 1);
    in.dp_static_si = 300;  // 3.3 %
    CHECK_THROWS_WITH(check_stability(in),
                      Catch::Contains("rho c_s^2") && Catch::Contains("lower dt to at most"));
  }
}

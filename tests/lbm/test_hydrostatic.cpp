// Hydrostatics: a closed column under a uniform force density rho0 g settles to dp/dz = -rho0 g,
// with the lattice pressure p = rho c_s^2, so rho falls linearly with height. The column's
// relative density change g H / c_s^2 is exactly what the static-pressure check of units.hpp
// predicts from the SI set-up (Dp / (rho c_s^2) with Dp = rho g H), so the check and the lattice
// are tested together. The lattice column runs in double (the reference) and in single precision
// (float populations f - w, float collision arithmetic: lbm/cell.hpp).
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/units.hpp"

#include <cmath>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

struct Column {
  double dp_measured, dp_exact, u_max;
};

/// A 4 x 4 x h column (periodic in x, y; walls below and above) under force density rho g in -z,
/// started from uniform density 1 at rest, in the given precision.
Column settle(int h, double g, Precision precision = Precision::float64) {
  LbmSettings s;
  s.nx = s.ny = 4;
  s.nz = h;
  s.faces[4].kind = FaceKind::wall;
  s.faces[5].kind = FaceKind::wall;
  // TRT at tau = 1: the column's acoustic modes decay as exp(-Gamma k^2 t) with Gamma of order
  // nu = 1/6; k = pi/h at h = 32 gives an e-fold every ~600 steps, so 20000 steps leave the
  // start-up transient (O(g h / c_s^2) in rho) below 1e-14 of it.
  s.collision = Trt::from_tau(1.0);
  s.precision = precision;
  LbmSolver lbm(s);
  // The gas weight as a uniform force density rho0 g (the scenarios' gravity on the gas): the
  // balance c_s^2 drho/dz = -rho0 g is then linear, and since the mean density stays rho0 (mass is
  // conserved) the bottom-to-top difference is the column's weight rho0 g H, as in SI.
  lbm.set_body_force(Vec3(0, 0, -g));
  for (int k = 0; k < 20000; ++k) lbm.step();
  // Between the outer cell centres, h - 1 cells apart.
  const double dp = kCs2 * (lbm.moments(1, 1, 0).rho - lbm.moments(1, 1, h - 1).rho);
  double u_max = 0;
  for (int z = 0; z < h; ++z) {
    const CellMoments m = lbm.moments(2, 2, z);
    u_max = std::max(u_max, std::sqrt(m.ux * m.ux + m.uy * m.uy + m.uz * m.uz));
  }
  return {dp, g * (h - 1), u_max};
}

}  // namespace

TEST_CASE("Hydrostatic column holds rho g H, and the pressure check predicts its density change",
          "[lbm]") {
  // SI column: air (1.2 kg/m^3, nu = 1.5e-5 m^2/s), 32 cells of dx = 1 mm, gravity 9.81 m/s^2, so
  // Dp = rho g H = 0.3767 Pa. The time step sets c_s and so Dp / (rho c_s^2) = 3 g H dt^2 / dx^2.
  const double rho = 1.2, nu = 1.5e-5, dx = 1e-3, g_si = 9.81;
  const int h = 32;
  const double dp_si = rho * g_si * h * dx;
  auto check_at = [&](double dt) {
    StabilityInput in;
    in.units = {dx, dt, rho};
    in.nu_si = nu;
    in.u_max_si = 0;
    in.dp_static_si = dp_si;
    return check_stability(in);
  };
  // dt for 0.5 %, 2 % and 5 % of rho c_s^2: dt = dx sqrt(fraction rho / (3 Dp)).
  const double dt_ok = max_dt_for_pressure(dp_si, rho, dx, 0.005);
  const double dt_warn = max_dt_for_pressure(dp_si, rho, dx, 0.02);
  const double dt_bad = max_dt_for_pressure(dp_si, rho, dx, 0.05);

  const StabilityReport ok = check_at(dt_ok);
  CHECK(ok.warnings.empty());
  CHECK(ok.density_change == Approx(0.005).epsilon(1e-12));
  CHECK(check_at(dt_warn).warnings.size() == 1);
  CHECK_THROWS_AS(check_at(dt_bad), InputError);

  // The lattice column at each of those steps: g_lattice = g dt^2 / dx. Its measured density
  // change must equal the check's prediction. The issue asks for 1 %; the balance is linear and
  // exact on the lattice and the transient has decayed, so what remains is round-off (measured
  // 4e-13): 1e-10 bounds it with room.
  for (double dt : {dt_ok, dt_warn, dt_bad}) {
    const double g = g_si * dt * dt / dx;
    const Column c = settle(h, g);
    INFO("dt " << dt << " g_lattice " << g << " dp " << c.dp_measured << " exact " << c.dp_exact
               << " u_max " << c.u_max);
    CHECK(c.dp_measured == Approx(c.dp_exact).epsilon(1e-10));
    // Predicted Dp / (rho c_s^2) over the full height H = h cells (walls half a cell beyond the
    // outer centres) against the measured one over h - 1 cells, scaled to h.
    CHECK(c.dp_measured / kCs2 * h / (h - 1) ==
          Approx(LatticeUnits{dx, dt, rho}.density_change(dp_si)).epsilon(1e-10));
    // Spurious velocity: Guo forcing and half-way walls balance a force exactly in a gas at
    // rest; measured 1.3e-13 of the column's velocity scale g h / c_s, bound 1e-11.
    CHECK(c.u_max < 1e-11 * g * h / std::sqrt(kCs2));
  }
}

TEST_CASE("Hydrostatic column in single precision holds rho g H to float round-off", "[lbm]") {
  // The same three columns (density changes of 0.5 %, 2 % and 5 % of rho over the height) with
  // float populations f - w. The lattice balance is exact, so float round-off is all that remains.
  // The stored deviations f - w are about w |drho| <= 0.025 w (the density is 1 at mid-height);
  // a step rounds each of them and the float collision's few operations on them to a few 2^-24
  // of itself: at most ~ 4 x 6e-8 x 0.025 = 6e-9 in rho and, over the links sum_q w_q |c_qz|
  // = 1/3, 2e-9 in u per step. The column forgets errors at its slowest acoustic mode's rate (an
  // e-fold every ~600 steps, above), so rounding that always went one way would settle at
  // 600 x 6e-9 = 3.6e-6 in rho and 1.2e-6 in u. The smallest column (0.5 %) has
  // Dp / c_s^2 = 4.8e-3 and g h / c_s = 2.9e-3: 2 x 3.6e-6 / 4.8e-3 = 1.5e-3 of Dp and 4e-4 of
  // the velocity scale at worst. Bounds 2e-3 and 5e-4, both far below the 1 % and any
  // error of the balance itself (a force off by its half-step shift is O(g) in u). Measured:
  // Dp within 1.0e-7 of exact, u_max 2.1e-7 of g h / c_s (a static state repeats its roundings,
  // which then stick: the worst case above is far from reached).
  const double rho = 1.2, dx = 1e-3, g_si = 9.81;
  const int h = 32;
  const double dp_si = rho * g_si * h * dx;
  for (const double fraction : {0.005, 0.02, 0.05}) {
    const double dt = max_dt_for_pressure(dp_si, rho, dx, fraction);
    const double g = g_si * dt * dt / dx;
    const Column c = settle(h, g, Precision::float32);
    INFO("density change " << fraction << " g_lattice " << g << " dp " << c.dp_measured << " exact "
                           << c.dp_exact << " relative error " << c.dp_measured / c.dp_exact - 1
                           << " u_max / (g h / c_s) " << c.u_max / (g * h / std::sqrt(kCs2)));
    CHECK(c.dp_measured == Approx(c.dp_exact).epsilon(2e-3));
    CHECK(c.dp_measured / kCs2 * h / (h - 1) ==
          Approx(LatticeUnits{dx, dt, rho}.density_change(dp_si)).epsilon(2e-3));
    CHECK(c.u_max < 5e-4 * g * h / std::sqrt(kCs2));
  }
}

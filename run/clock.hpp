#pragma once
// How the gas and the DEM share time in a coupled run (docs/physics.md, Coupled time step): an
// integer number of gas steps per DEM step or of DEM steps per gas step, and the exchange interval
// of whole such cycles. The gas step is the one the config fixes (it sets tau, Mach and
// Dp / (rho c_s^2)); the DEM step is only ever shortened to fit.
#include <cstdint>

namespace lbdem::run {

struct SubCycle {
  int gas_per_dem = 1;                  // > 1: the DEM step holds this many gas steps
  int dem_per_gas = 1;                  // > 1: the gas step holds this many DEM steps
  double dem_dt_asked = 0, dem_dt = 0;  // [s]
  /// DEM steps per coupling cycle: instants where both solvers stand at the same time.
  std::int64_t cycle() const { return dem_per_gas; }
  /// Gas steps to take before DEM step number `dem_step` (0-based): the gas leads, so the DEM
  /// steps of a cycle see the gas at the cycle's end (docs/physics.md, Coupled time step: LBM, then
  /// DEM).
  int gas_steps_before(std::int64_t dem_step) const {
    return dem_per_gas > 1 ? (dem_step % dem_per_gas == 0 ? 1 : 0) : gas_per_dem;
  }
};

/// dt_dem >= dt_gas: dt_dem = n dt_gas with n = floor(dt_dem / dt_gas); else dt_dem = dt_gas / m
/// with m = ceil(dt_gas / dt_dem). Both only shorten the DEM step, so its t_c/20 check still holds.
SubCycle conform_dem_step(double dem_dt, double gas_dt);

/// DEM steps per exchange interval and gas steps in it.
struct ExchangeInterval {
  std::int64_t dem_steps = 1;
  int gas_steps = 1;
};
/// The interval of `exchange_every` coupling cycles.
ExchangeInterval exchange_interval(const SubCycle& sub, int exchange_every);

}  // namespace lbdem::run

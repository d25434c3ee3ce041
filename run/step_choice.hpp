#pragma once
// The DEM time step a scenario chose and why (scenarios/common/dem_config.hpp reads it from
// [dem]), with the watchdog's limits: what the loop's divergence messages offer as the fix.
#include "dem/time_step.hpp"

namespace lbdem::run {

struct StepChoice {
  double dt, impact_speed;  // [s], [m/s]
  dem::TimeScales scales;
  double dt_factor = 1;  // the parcels' step over dem.dt (coarse graining)
  bool forced = false;   // dem.force_dt
  // The DEM watchdog's limits (run_loop.hpp, DemWatch): dem.max_speed_factor and
  // dem.max_energy_error.
  double max_speed_factor = 10, max_energy_error = 0.1;
};

}  // namespace lbdem::run

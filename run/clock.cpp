#include "run/clock.hpp"

#include <cmath>

namespace lbdem::run {

SubCycle conform_dem_step(double dem_dt, double gas_dt) {
  SubCycle s;
  s.dem_dt_asked = dem_dt;
  const double r = dem_dt / gas_dt;
  // The 1e-9 keeps a ratio meant to be whole (3 dt_gas given as 2.9999999999 dt_gas) whole.
  if (r >= 1 - 1e-9) {
    s.gas_per_dem = static_cast<int>(std::floor(r * (1 + 1e-9)));
    s.dem_dt = s.gas_per_dem * gas_dt;
  } else {
    s.dem_per_gas = static_cast<int>(std::ceil(1 / r * (1 - 1e-9)));
    s.dem_dt = gas_dt / s.dem_per_gas;
  }
  return s;
}

ExchangeInterval exchange_interval(const SubCycle& sub, int every) {
  ExchangeInterval e;
  if (sub.dem_per_gas > 1) {
    e.dem_steps = std::int64_t(every) * sub.dem_per_gas;
    e.gas_steps = every;
  } else {
    e.dem_steps = every;
    e.gas_steps = every * sub.gas_per_dem;
  }
  return e;
}

}  // namespace lbdem::run

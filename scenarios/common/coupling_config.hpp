#pragma once
// [coupling] of a scenario with a gas and particles: the two-way exchange of coupling/coupler.hpp.
// Keys (all optional):
//   two_way = true (false: the gas acts on the particles only), drag = "gidaspow" (any law of
//   coupling/drag/drag_model.hpp), kernel_width [m] (default max(dx, 2 D) for the largest parcel
//   diameter D, kernel.hpp), eps_min (0.3), pressure_gradient = true (-V_p grad p),
//   exchange_every = 1 (coupling cycles per exchange; a cycle is one gas step or one DEM step,
//   whichever is longer).
// The banner gives the numbers the issue asks for: particle Reynolds and Stokes numbers, cells per
// parcel diameter, parcels per cell, kernel width over parcel diameter, both steps and their ratio,
// and the explicit particle-side drag rate.
#include <cstdint>
#include <string>

#include "core/config.hpp"
#include "core/log.hpp"
#include "coupling/coupler.hpp"
#include "scenarios/common/fluid_config.hpp"

namespace lbdem::scenarios {

struct CouplingConfig {
  coupling::CouplerSettings settings;
  int exchange_every = 1;
  double parcel_diameter_max = 0, parcel_diameter_min = 0;  // [m]
  double particle_density = 0;                              // of the first material [kg/m^3]
};

/// Reads [coupling]. d_min, d_max: smallest and largest parcel diameters [m]; l: parcel size
/// factor; rho_p: particle density [kg/m^3]; gravity [m/s^2] (the gas's weight is taken out of
/// the exchange where fluid.gravity puts it on the gas).
CouplingConfig read_coupling(const Config& c, const FluidConfig& fluid, double d_min, double d_max,
                             double l, double rho_p, bool gas_weighs, const Vec3& gravity);

using run::exchange_interval;
using run::ExchangeInterval;

void coupling_banner(Log& log, const CouplingConfig& c, const FluidConfig& fluid,
                     const SubCycle& sub, std::size_t particles, double fluid_cells);

}  // namespace lbdem::scenarios

#pragma once
// Time-step estimates from the contact time and the Rayleigh time (docs/physics.md, DEM time step).
#include <string>
#include <vector>

#include "dem/contact/registry.hpp"
#include "dem/material.hpp"

namespace lbdem::dem {

struct TimeScales {
  double contact_time;   // shortest contact duration at the impact speed [s]
  double rayleigh_time;  // shortest Rayleigh-wave time [s]
  std::string where;     // which pair gives the contact time
};

/// Shortest contact time among particle-particle (smallest particle, same material) and
/// particle-wall pairs at impact speed v_impact.
TimeScales time_scales(const ContactSettings& s, const std::vector<Material>& materials,
                       const std::vector<int>& wall_materials, double r_min, double v_impact);

}  // namespace lbdem::dem

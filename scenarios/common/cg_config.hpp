#pragma once
// [coarse_grain] in every DEM scenario: the config gives the ORIGINAL particles (materials, sizes,
// dt); with a size factor l > 1 the scenario simulates parcels of l times the radius whose contact
// parameters follow the chosen rule (coarse_grain/). Masses to fill are kept; particle counts to
// fill are parcel counts.
#include <string>
#include <vector>

#include "coarse_grain/scale.hpp"
#include "core/config.hpp"
#include "core/log.hpp"
#include "dem/material.hpp"

namespace lbdem::scenarios {

struct CoarseGrain {
  cg::CgSettings settings;  // rule, cohesion rule, l
  bool scale_dt = true;     // multiply a given dem.dt by the rule's time-step factor
  std::vector<std::string> banner;

  double l() const { return settings.size_factor; }
  bool on() const { return settings.size_factor != 1.0; }
  /// Replaces each material by its parcel material; `radius` is a representative original radius
  /// (banner only: every rule's material scaling is independent of it). Fills `banner`.
  void apply(std::vector<dem::Material>& mats, double radius);
  /// dt_cg / dt of the rule (1 if off or scale_dt is false).
  double dt_factor(const dem::Material& m, double radius) const;
};

/// Reads [coarse_grain] (rule, cohesion, size_factor or particles_per_parcel, scale_dt); checks
/// that the rule suits contact.normal.
CoarseGrain read_coarse_grain(const Config& c, const std::string& normal_law);

}  // namespace lbdem::scenarios

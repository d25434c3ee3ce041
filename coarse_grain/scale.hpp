#pragma once
// The parcel parameters of one material under the chosen rules, and the start-up banner that sets
// them beside the original's.
#include <string>
#include <vector>

#include "coarse_grain/scaling_rule.hpp"
#include "dem/material.hpp"

namespace lbdem::cg {

/// Parameters of a parcel (or, at l = 1, of an original particle). SI units.
struct ParcelParameters {
  ScalingRule rule;
  CohesionRule cohesion;
  double size_factor;           // l [-]
  double particles_per_parcel;  // l^3 [-]
  double radius;                // [m]
  double density;               // [kg/m^3] (kept: a parcel is a sphere of the original solid)
  double mass;                  // [kg]
  double stiffness;             // linear k_n [N/m] (linear rules)
  double youngs_modulus;        // E [Pa] (hertz)
  double poisson_ratio;         // nu [-]
  double restitution;           // e the engine should be given (equal-parcel pair) [-]
  double damping;               // absolute normal gamma, equal-parcel pair [N s/m]; 0 for hertz
  double friction;              // sliding mu [-], kept
  double rolling_friction;      // mu_r [-], kept (rolling_scaling.hpp)
  double hamaker;               // A [J] (cohesion_scaling.hpp)
  double time_step_factor;      // dt_cg / dt at the same steps per contact [-]
};

/// Applies settings.rule and settings.cohesion to a material of original radius `radius` [m].
ParcelParameters scale(const dem::Material& m, double radius, const CgSettings& settings);

/// The original particle described in the same terms (the rules at l = 1).
ParcelParameters original(const dem::Material& m, double radius, const CgSettings& settings);

/// The material to give the engine for parcels: `m` with the scaled stiffness, restitution and
/// Hamaker constant (the rest is kept by every rule); the name gets a "_cg" suffix only if l > 1.
dem::Material parcel_material(const dem::Material& m, const ParcelParameters& p);

/// Start-up banner: a header naming the rules, references and invariants, then one line per
/// quantity with the original value, the parcel value and their ratio.
std::vector<std::string> side_by_side(const ParcelParameters& original,
                                      const ParcelParameters& parcel);

}  // namespace lbdem::cg

#pragma once
// Names of the coarse-graining rules and the validated [coarse_grain] input. Size factor l: a
// parcel has l times the original diameter, the original density and stands for l^3 originals.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lbdem::cg {

/// Contact scaling rules (stiffness_scaling.hpp gives each one's equations and reference).
enum class ScalingRule { stiffness_only, linear_similarity, hertz };
/// Cohesion scaling rules (cohesion_scaling.hpp).
enum class CohesionRule { tensile_strength, bond_number, unscaled };

/// One row of the rule table (a checked-in name table): the names the config accepts, the normal
/// law the parcel parameters are meant for, the reference and the invariant the rule keeps.
struct RuleInfo {
  ScalingRule rule;
  std::string_view name;
  std::string_view normal_law;  // dem contact.normal the rule is written for
  std::string_view reference;
  std::string_view keeps;
};
struct CohesionRuleInfo {
  CohesionRule rule;
  std::string_view name;
  std::string_view force_scaling;  // F_cg / F at the same gap
  std::string_view reference;
  std::string_view keeps;
};

const RuleInfo& info(ScalingRule r);
const CohesionRuleInfo& info(CohesionRule r);
std::vector<std::string> rule_names();
std::vector<std::string> cohesion_rule_names();

/// The rule called `name`; InputError naming `key`, the value and the known names otherwise.
ScalingRule rule_from_name(std::string_view name, const std::string& key);
CohesionRule cohesion_rule_from_name(std::string_view name, const std::string& key);

/// l = n^(1/3) for n original particles per parcel, and back (n = l^3). The jet-mill study names
/// its cases by n, as the seed study does; the rheometer study by l.
double size_factor_from_particles_per_parcel(double n);
double particles_per_parcel(double size_factor);

/// [coarse_grain] as read from a config: strings and numbers not yet checked. size_factor and
/// particles_per_parcel are alternatives (give one; if both are given they must agree).
struct CgInput {
  std::string rule = "linear_similarity";
  std::string cohesion = "bond_number";
  std::optional<double> size_factor;           // l [-]
  std::optional<double> particles_per_parcel;  // n = l^3 [-]
};

/// Checked settings: l >= 1 (a parcel is never smaller than an original), known rule names.
struct CgSettings {
  ScalingRule rule = ScalingRule::linear_similarity;
  CohesionRule cohesion = CohesionRule::bond_number;
  double size_factor = 1.0;  // l [-]
};

/// The fixes validate gives for a size below 1 (the config reader gives them for one not finite).
inline constexpr std::string_view kSizeFactorFix =
    "give a size factor l >= 1 (parcel diameter / original diameter)";
inline constexpr std::string_view kParticlesPerParcelFix =
    "give particles_per_parcel >= 1 (= size_factor^3)";

/// Validates `in`; errors are InputError with keys under `section` ("coarse_grain.rule", ...).
/// Neither size given: l = 1 (no coarse graining).
CgSettings validate(const CgInput& in, const std::string& section = "coarse_grain");

}  // namespace lbdem::cg

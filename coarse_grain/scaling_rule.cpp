#include "coarse_grain/scaling_rule.hpp"

#include <array>
#include <cmath>

#include "core/config.hpp"
#include "core/error.hpp"

namespace lbdem::cg {

namespace {

constexpr std::array<RuleInfo, 3> kRules = {{
    {ScalingRule::stiffness_only, "stiffness_only", "linear",
     "the rheometer seed's k_cg = l k, damping coefficient read as absolute",
     "t_c / l to O(zeta^2); NOT e (zeta falls as 1/l^2)"},
    {ScalingRule::linear_similarity, "linear_similarity", "linear",
     "Bierwisch et al. 2009, J. Mech. Phys. Solids 57:10; Radl et al. 2011",
     "e, delta_max/d, t_c/l, energy per unit volume"},
    {ScalingRule::hertz, "hertz", "hertz_mindlin",
     "Hertz-Mindlin with E, nu unchanged (Johnson 1985 eq. 4.23; Thakur et al. 2016)",
     "e, delta_max/d, t_c/l, contact stress"},
}};

constexpr std::array<CohesionRuleInfo, 3> kCohesionRules = {{
    {CohesionRule::tensile_strength, "tensile_strength", "l^2",
     "Thakur, Ooi & Ahmadian 2016, Powder Technol. 293:130", "bulk tensile strength ~ F/d^2"},
    {CohesionRule::bond_number, "bond_number", "l^3",
     "energy-based CG (Sakai & Koshizuka 2009; Sakai et al. 2012, Adv. Powder Technol. 23:673)",
     "Bond number F/(m g), cohesive energy per unit mass"},
    {CohesionRule::unscaled, "unscaled", "l",
     "baseline: the original Hamaker constant (F grows with R* only)", "nothing"},
}};

// info() indexes the tables by the enum's value.
template <class Table>
constexpr bool indexed_by_rule(const Table& t) {
  for (std::size_t i = 0; i < t.size(); ++i)
    if (static_cast<std::size_t>(t[i].rule) != i) return false;
  return true;
}
static_assert(indexed_by_rule(kRules) && indexed_by_rule(kCohesionRules));

template <class Table>
std::vector<std::string> names_of(const Table& t) {
  std::vector<std::string> out;
  for (const auto& r : t) out.emplace_back(r.name);
  return out;
}

template <class Table>
auto from_name(const Table& t, std::string_view name, const std::string& key, const char* what) {
  for (const auto& r : t)
    if (r.name == name) return r.rule;
  const auto names = names_of(t);
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw InputError(key, "\"" + std::string(name) + "\"",
                   std::string("unknown ") + what + "; known: " + list,
                   "did you mean \"" + nearest(name, names) + "\"?");
}

}  // namespace

const RuleInfo& info(ScalingRule r) {
  return kRules[static_cast<std::size_t>(r)];
}
const CohesionRuleInfo& info(CohesionRule r) {
  return kCohesionRules[static_cast<std::size_t>(r)];
}
std::vector<std::string> rule_names() {
  return names_of(kRules);
}
std::vector<std::string> cohesion_rule_names() {
  return names_of(kCohesionRules);
}

ScalingRule rule_from_name(std::string_view name, const std::string& key) {
  return from_name(kRules, name, key, "coarse-graining rule");
}
CohesionRule cohesion_rule_from_name(std::string_view name, const std::string& key) {
  return from_name(kCohesionRules, name, key, "cohesion scaling rule");
}

double size_factor_from_particles_per_parcel(double n) {
  return std::cbrt(n);
}
double particles_per_parcel(double l) {
  return l * l * l;
}

CgSettings validate(const CgInput& in, const std::string& section) {
  const auto key = [&](const char* k) { return section + "." + k; };
  CgSettings s;
  s.rule = rule_from_name(in.rule, key("rule"));
  s.cohesion = cohesion_rule_from_name(in.cohesion, key("cohesion"));
  const auto& l = in.size_factor;
  const auto& n = in.particles_per_parcel;
  // !(x >= 1) also rejects NaN.
  if (l && !(*l >= 1 && std::isfinite(*l)))
    throw InputError(key("size_factor"), shortest_text(*l),
                     "a parcel cannot be smaller than an original particle",
                     std::string(kSizeFactorFix));
  if (n && !(*n >= 1 && std::isfinite(*n)))
    throw InputError(key("particles_per_parcel"), shortest_text(*n),
                     "a parcel stands for at least one original particle",
                     std::string(kParticlesPerParcelFix));
  if (l && n) {
    // 1e-6: values typed by hand carry ~6 digits (8 parcels of 2.0, 4.096 of 1.6); a real mismatch
    // is far larger.
    if (std::abs(size_factor_from_particles_per_parcel(*n) - *l) > 1e-6 * *l)
      throw InputError(key("particles_per_parcel"), shortest_text(*n),
                       "disagrees with size_factor = " + shortest_text(*l) +
                           " (it needs particles_per_parcel = size_factor^3 = " +
                           to_text(particles_per_parcel(*l)) + ")",
                       "give only one of size_factor and particles_per_parcel");
  }
  s.size_factor = l ? *l : n ? size_factor_from_particles_per_parcel(*n) : 1.0;
  return s;
}

}  // namespace lbdem::cg

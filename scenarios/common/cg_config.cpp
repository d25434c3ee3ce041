#include "scenarios/common/cg_config.hpp"

#include "core/error.hpp"

namespace lbdem::scenarios {

CoarseGrain read_coarse_grain(const Config& c, const std::string& normal_law) {
  cg::CgInput in;
  in.rule = c.get_string("rule", in.rule);
  in.cohesion = c.get_string("cohesion", in.cohesion);
  // The range (>= 1) is cg::validate's, with the reason; a "> 0" range here would fire first on
  // a negative value and contradict its own fix. Only a value that is not finite stops here,
  // with the same fix.
  if (c.has("size_factor"))
    in.size_factor = c.get("size_factor", 1.0, Range{.fix = cg::kSizeFactorFix});
  if (c.has("particles_per_parcel"))
    in.particles_per_parcel =
        c.get("particles_per_parcel", 1.0, Range{.fix = cg::kParticlesPerParcelFix});
  CoarseGrain out;
  out.settings = cg::validate(in, "coarse_grain");
  out.scale_dt = c.get_bool("scale_dt", true);
  const auto& info = cg::info(out.settings.rule);
  if (out.on() && info.normal_law != normal_law)
    throw InputError(c.path("rule"), "\"" + std::string(info.name) + "\"",
                     "is written for contact.normal = \"" + std::string(info.normal_law) +
                         "\", but the config uses \"" + normal_law + "\"",
                     "choose a rule for " + normal_law +
                         " (linear: stiffness_only, "
                         "linear_similarity; hertz_mindlin: hertz)");
  return out;
}

void CoarseGrain::apply(std::vector<dem::Material>& mats, double radius) {
  banner.clear();
  if (!on()) return;
  for (auto& m : mats) {
    const auto o = cg::original(m, radius, settings);
    const auto p = cg::scale(m, radius, settings);
    banner.push_back("material " + m.name + ":");
    for (auto& line : cg::side_by_side(o, p)) banner.push_back(line);
    m = cg::parcel_material(m, p);
  }
}

double CoarseGrain::dt_factor(const dem::Material& m, double radius) const {
  if (!on() || !scale_dt) return 1.0;
  return cg::scale(m, radius, settings).time_step_factor;
}

}  // namespace lbdem::scenarios

#include "coarse_grain/scale.hpp"

#include <cstdio>

#include "coarse_grain/cohesion_scaling.hpp"
#include "coarse_grain/stiffness_scaling.hpp"
#include "core/types.hpp"

namespace lbdem::cg {

ParcelParameters scale(const dem::Material& m, double radius, const CgSettings& s) {
  const double l = s.size_factor;
  NormalContact c{};
  switch (s.rule) {
    case ScalingRule::stiffness_only:
      c = stiffness_only(m, radius, l);
      break;
    case ScalingRule::linear_similarity:
      c = linear_similarity(m, radius, l);
      break;
    case ScalingRule::hertz:
      c = hertz(m, radius, l);
      break;
  }
  ParcelParameters p{};
  p.rule = s.rule;
  p.cohesion = s.cohesion;
  p.size_factor = l;
  p.particles_per_parcel = particles_per_parcel(l);
  p.radius = l * radius;
  p.density = m.density;
  p.mass = m.density * 4.0 / 3.0 * kPi * p.radius * p.radius * p.radius;
  p.stiffness = c.stiffness;
  p.youngs_modulus = c.youngs_modulus;
  p.poisson_ratio = m.poisson_ratio;
  p.restitution = c.restitution;
  p.damping = c.damping;
  p.friction = m.friction;
  p.rolling_friction = m.rolling_friction;
  p.hamaker = scaled_hamaker(m.hamaker, l, s.cohesion);
  p.time_step_factor = c.time_step_factor;
  return p;
}

ParcelParameters original(const dem::Material& m, double radius, const CgSettings& s) {
  CgSettings one = s;
  one.size_factor = 1.0;
  return scale(m, radius, one);
}

dem::Material parcel_material(const dem::Material& m, const ParcelParameters& p) {
  dem::Material out = m;
  if (p.size_factor > 1) out.name += "_cg";
  out.stiffness = p.stiffness;
  out.youngs_modulus = p.youngs_modulus;
  out.restitution = p.restitution;
  out.hamaker = p.hamaker;
  return out;
}

namespace {
std::string row(const char* name, double a, double b, const char* unit) {
  char buf[160];
  if (a != 0)
    std::snprintf(buf, sizeof buf, "  %-22s %13.6g %13.6g %10.4g  %s", name, a, b, b / a, unit);
  else
    std::snprintf(buf, sizeof buf, "  %-22s %13.6g %13.6g %10s  %s", name, a, b, "-", unit);
  return buf;
}
}  // namespace

std::vector<std::string> side_by_side(const ParcelParameters& o, const ParcelParameters& p) {
  const RuleInfo& r = info(p.rule);
  const CohesionRuleInfo& c = info(p.cohesion);
  std::vector<std::string> out;
  char head[160];
  std::snprintf(head, sizeof head,
                "coarse graining: size factor l = %.6g, %.6g originals per parcel", p.size_factor,
                p.particles_per_parcel);
  out.emplace_back(head);
  out.push_back("  contact rule " + std::string(r.name) + " (normal law " +
                std::string(r.normal_law) + "): " + std::string(r.reference));
  out.push_back("    keeps: " + std::string(r.keeps));
  out.push_back("  cohesion rule " + std::string(c.name) +
                " (F_cg = " + std::string(c.force_scaling) +
                " F, cut-offs absolute): " + std::string(c.reference));
  out.push_back("    keeps: " + std::string(c.keeps));
  char cols[160];
  std::snprintf(cols, sizeof cols, "  %-22s %13s %13s %10s  %s", "quantity", "original", "parcel",
                "ratio", "unit");
  out.emplace_back(cols);
  out.push_back(row("radius", o.radius, p.radius, "m"));
  out.push_back(row("density", o.density, p.density, "kg/m^3"));
  out.push_back(row("mass", o.mass, p.mass, "kg"));
  if (r.normal_law == "linear") {
    out.push_back(row("stiffness k_n", o.stiffness, p.stiffness, "N/m"));
    out.push_back(row("damping gamma (pair)", o.damping, p.damping, "N s/m"));
  } else {
    out.push_back(row("Young's modulus E", o.youngs_modulus, p.youngs_modulus, "Pa"));
    out.push_back(row("Poisson ratio", o.poisson_ratio, p.poisson_ratio, "-"));
  }
  out.push_back(row("restitution e", o.restitution, p.restitution, "-"));
  out.push_back(row("sliding friction", o.friction, p.friction, "-"));
  out.push_back(row("rolling friction", o.rolling_friction, p.rolling_friction, "-"));
  out.push_back(row("Hamaker constant", o.hamaker, p.hamaker, "J"));
  out.push_back(row("time-step factor", o.time_step_factor, p.time_step_factor, "-"));
  return out;
}

}  // namespace lbdem::cg

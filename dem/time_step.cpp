#include "dem/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace lbdem::dem {

TimeScales time_scales(const ContactSettings& s, const std::vector<Material>& materials,
                       const std::vector<int>& wall_materials, double r, double v) {
  TimeScales out{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                 ""};
  const NormalVariant normal = normal_law(s.normal);  // the configured law's own contact time
  const auto consider = [&](const MaterialPair& mp, double r_star, double m_star,
                            const std::string& what) {
    const double tc = std::visit(
        [&](auto law) { return decltype(law)::contact_time(mp, r_star, m_star, v); }, normal);
    if (tc < out.contact_time) out.contact_time = tc, out.where = what;
  };
  for (std::size_t a = 0; a < materials.size(); ++a) {
    const Material& m = materials[a];
    const double mass = m.density * 4.0 / 3.0 * kPi * r * r * r;
    consider(mix(m, m), 0.5 * r, 0.5 * mass, m.name + "-" + m.name);
    for (int w : wall_materials) consider(mix(m, materials[w]), r, mass, m.name + "-wall");
    out.rayleigh_time = std::min(out.rayleigh_time,
                                 rayleigh_time(r, m.density, m.shear_modulus(), m.poisson_ratio));
  }
  return out;
}

}  // namespace lbdem::dem

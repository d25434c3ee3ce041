#include "coarse_grain/stiffness_scaling.hpp"

#include <cmath>

#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/restitution.hpp"

namespace lbdem::cg {

namespace {
/// m* of two equal spheres of the material [kg].
double pair_mass(const dem::Material& m, double radius) {
  return 0.5 * m.density * 4.0 / 3.0 * kPi * radius * radius * radius;
}
}  // namespace

double linear_restitution(double zeta) {
  if (zeta >= 1) return 0.0;
  return std::exp(-kPi * zeta / std::sqrt(1 - zeta * zeta));
}

double linear_damping_ratio(double e) {
  return std::abs(dem::restitution_beta(e));
}

NormalContact stiffness_only(const dem::Material& m, double radius, double l) {
  const double m0 = pair_mass(m, radius), m_cg = l * l * l * m0;
  const double k_cg = l * m.stiffness;
  const double zeta0 = linear_damping_ratio(m.restitution);
  const double gamma = 2 * zeta0 * std::sqrt(m0 * m.stiffness);  // the original's, kept
  const double zeta = gamma / (2 * std::sqrt(m_cg * k_cg));      // = zeta0 / l^2
  const double t0 = dem::linear_contact_time(m.stiffness, gamma, m0);
  const double t_cg = dem::linear_contact_time(k_cg, gamma, m_cg);
  // At or above critical damping (e = 0) the original has no oscillation time; the undamped
  // period ratio sqrt(m_cg k / (m0 k_cg)) = l is then the scale of the step.
  const double dt_factor = t0 > 0 && t_cg > 0 ? t_cg / t0 : l;
  return {k_cg, m.youngs_modulus, linear_restitution(zeta), gamma, dt_factor};
}

NormalContact linear_similarity(const dem::Material& m, double radius, double l) {
  const double m_cg = l * l * l * pair_mass(m, radius);
  const double k_cg = l * m.stiffness;
  const double gamma = 2 * linear_damping_ratio(m.restitution) * std::sqrt(m_cg * k_cg);  // ~ l^2
  return {k_cg, m.youngs_modulus, m.restitution, gamma, l};
}

NormalContact hertz(const dem::Material& m, double /*radius*/, double l) {
  return {m.stiffness, m.youngs_modulus, m.restitution, 0.0, l};
}

}  // namespace lbdem::cg

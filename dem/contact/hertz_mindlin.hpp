#pragma once
// Hertz normal + Mindlin no-slip tangential stiffness, Tsuji et al. (1992) damping.
#include <cmath>
#include <string_view>

#include "dem/contact/restitution.hpp"
#include "dem/material.hpp"

namespace lbdem::dem {

/// F_n = 4/3 E* sqrt(R*) delta^{3/2} + gamma v_n with gamma = sqrt5 |beta(e)| sqrt(m* k_n) and the
/// secant stiffness k_n = 4/3 E* sqrt(R* delta) (Tsuji et al. 1992, eq. 15; identical to LIGGGHTS'
/// 2 sqrt(5/6) |beta| sqrt(m* S_n) with S_n = 2 E* sqrt(R* delta)). Convention: the normal force is
/// NOT clipped at zero, the contact lasts until delta = 0, and the restitution is velocity
/// independent. Tangential: k_t = 8 G* sqrt(R* delta) (Mindlin 1949), gamma_t = 2 sqrt(5/6) |beta|
/// sqrt(m* k_t) (LIGGGHTS' tangential damping).
struct HertzMindlin {
  struct Params {
    double e_star;   // [Pa]
    double g_star;   // [Pa]
    double c_damp;   // sqrt5 |beta(e)| [-]
    double t_ratio;  // gamma_t / gamma_n = 2 sqrt(G*/E*) [-]
  };
  static constexpr std::string_view name = "hertz_mindlin";

  struct State {
    double f_el, k_n, k_t, u_el;
  };
  static State elastic(const Params& p, double delta, double r_star) {
    const double a = std::sqrt(r_star * delta);  // contact radius
    const double kn = 4.0 / 3.0 * p.e_star * a;
    const double f = kn * delta;
    return {f, kn, 8.0 * p.g_star * a, 0.4 * f * delta};  // U = 8/15 E* sqrt(R*) delta^{5/2}
  }
  static double gamma(const Params& p, const State& s, double m_star) {
    return p.c_damp * std::sqrt(m_star * s.k_n);
  }
  /// gamma_t / gamma_n = (c_t/c_n) sqrt(k_t/k_n) = (2/sqrt6) sqrt(6 G*/E*) = 2 sqrt(G*/E*): one
  /// square root per contact instead of two.
  static double tangential_damping_ratio(const Params& p) { return p.t_ratio; }

  /// kt_ratio is the linear law's (k_t / k_n); Mindlin's k_t follows from G* and is not set.
  static Params from(const MaterialPair& m, double /*kt_ratio*/) {
    const double b = std::abs(restitution_beta(m.restitution));
    return {m.e_star, m.g_star, std::sqrt(5.0) * b, 2.0 * std::sqrt(m.g_star / m.e_star)};
  }

  /// Duration of a normal contact of this pair at impact speed v_impact, elastic (Johnson's):
  /// what the time-step check and dem.steps_per_contact resolve.
  static double contact_time(const MaterialPair& m, double r_star, double m_star, double v_impact);
};

/// Hertz contact duration at impact speed v (elastic): t_c = 2.868 (m*^2/(R* E*^2 v))^{1/5}
/// (Johnson 1985, eq. 11.24).
inline double hertz_contact_time(double e_star, double r_star, double m_star, double v) {
  return 2.868 * std::pow(m_star * m_star / (r_star * e_star * e_star * v), 0.2);
}

inline double HertzMindlin::contact_time(const MaterialPair& m, double r_star, double m_star,
                                         double v_impact) {
  return hertz_contact_time(m.e_star, r_star, m_star, v_impact);
}

/// Rayleigh time pi R sqrt(rho/G) / (0.1631 nu + 0.8766) (Li, Xu & Thornton 2005).
inline double rayleigh_time(double radius, double density, double shear_modulus, double poisson) {
  return kPi * radius * std::sqrt(density / shear_modulus) / (0.1631 * poisson + 0.8766);
}

}  // namespace lbdem::dem

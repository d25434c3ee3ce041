#pragma once
// Linear spring-dashpot normal law (Cundall & Strack 1979) with damping for a given restitution.
#include <cmath>
#include <string_view>

#include "dem/contact/restitution.hpp"
#include "dem/material.hpp"

namespace lbdem::dem {

/// F_n = k delta + gamma v_n, gamma = 2 |beta(e)| sqrt(m* k). The force is not clipped at zero, so
/// the contact ends when delta returns to 0 and the restitution is exactly e (linear ODE, closed
/// form). Tangential spring k_t = kt_ratio k (2/7 gives equal normal and tangential periods for a
/// sphere).
struct LinearSpringDashpot {
  struct Params {
    double k;          // normal stiffness [N/m]
    double c_damp;     // gamma / sqrt(m* k) [-]
    double kt_ratio;   // k_t / k_n [-]
    double gamma_abs;  // if > 0: absolute damping coefficient [N s/m] overriding c_damp
    double t_ratio;    // gamma_t / gamma_n = sqrt(k_t / k_n) [-]
  };
  static constexpr std::string_view name = "linear";

  struct State {
    double f_el, k_n, k_t, u_el;
  };
  static State elastic(const Params& p, double delta, double /*r_star*/) {
    return {p.k * delta, p.k, p.kt_ratio * p.k, 0.5 * p.k * delta * delta};
  }
  static double gamma(const Params& p, const State& s, double m_star) {
    return p.gamma_abs > 0 ? p.gamma_abs : p.c_damp * std::sqrt(m_star * s.k_n);
  }
  /// gamma_t / gamma_n: the same damping ratio as the normal dashpot, gamma_t = c sqrt(m* k_t), so
  /// gamma_t / gamma_n = sqrt(k_t / k_n).
  static double tangential_damping_ratio(const Params& p) { return p.t_ratio; }

  static Params from(const MaterialPair& m, double kt_ratio) {
    return {m.stiffness, 2.0 * std::abs(restitution_beta(m.restitution)), kt_ratio, 0.0,
            std::sqrt(kt_ratio)};
  }

  /// Duration of a normal contact of this pair (effective radius and mass), damped as from():
  /// what the time-step check and dem.steps_per_contact resolve. Independent of the speed.
  static double contact_time(const MaterialPair& m, double r_star, double m_star, double v_impact);
};

/// Contact duration of the linear law: pi / sqrt(k/m* - (gamma/2m*)^2).
inline double linear_contact_time(double k, double gamma, double m_star) {
  const double w2 = k / m_star - (gamma / (2 * m_star)) * (gamma / (2 * m_star));
  return w2 > 0 ? kPi / std::sqrt(w2) : 0.0;
}

inline double LinearSpringDashpot::contact_time(const MaterialPair& m, double /*r_star*/,
                                                double m_star, double /*v_impact*/) {
  const double gamma =
      2.0 * std::abs(restitution_beta(m.restitution)) * std::sqrt(m_star * m.stiffness);
  return linear_contact_time(m.stiffness, gamma, m_star);
}

}  // namespace lbdem::dem

#pragma once
// Two-relaxation-time collision (Ginzburg, Verhaeghe & d'Humieres 2008, Commun. Comput. Phys. 3,
// 427): the even and odd parts f_q^{+-} = (f_q +- f_qbar)/2 relax with omega+ and omega-,
//   f_q <- f_q - omega+ (f^+ - f^{eq+}) - omega- (f^- - f^{eq-}) + (1 - omega+/2) S^+ + (1 -
//   omega-/2) S^-,
// where omega+ sets the viscosity and the "magic" parameter
//   Lambda = (1/omega+ - 1/2)(1/omega- - 1/2)
// fixes all steady errors: at Lambda = 3/16 half-way bounce-back puts a Poiseuille wall exactly
// half-way, and the parabola is exact (Ginzburg & d'Humieres 2003, Phys. Rev. E 68, 066614).
#include "lbm/cell.hpp"
#include "lbm/collision/collision_operator.hpp"
#include "lbm/d3q19.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace lbdem::lbm {

struct Trt {
  static constexpr std::string_view name = "trt";
  static constexpr double kMagicDefault = 3.0 / 16.0;
  double omega_plus;   // even rate: viscosity nu = c_s^2 (1/omega+ - 1/2)
  double omega_minus;  // odd rate, from Lambda

  static Trt from_tau(double tau, double magic = kMagicDefault) {
    if (!(tau > 0.5))
      throw std::invalid_argument("TRT needs tau > 1/2, got " + std::to_string(tau));
    if (!(magic > 0))
      throw std::invalid_argument("TRT needs Lambda > 0, got " + std::to_string(magic));
    const double tau_minus = 0.5 + magic / (tau - 0.5);
    return {1.0 / tau, 1.0 / tau_minus};
  }
  double magic() const { return (1.0 / omega_plus - 0.5) * (1.0 / omega_minus - 0.5); }
  double viscosity() const { return viscosity_from_tau(1.0 / omega_plus); }

  // always_inline: see regularized_les.hpp (a call left in the omp simd cell loop runs scalar).
  // R: double on f_q, float on f_q - w_q (cell.hpp, kShifted), where the even equilibrium is
  // formed shifted: w_q (drho + rho (...)); the odd part and the sources do not change.
  template <bool kForced, class R>
  [[gnu::always_inline]] void relax(R (&f)[kQ], const CellMomentsT<R>& m,
                                    const CellForceT<R>& force) const {
    const R op = R(omega_plus), om = R(omega_minus);
    // Terms of second order in u carry 1/eps (porous form, forcing/porous.hpp; 1 otherwise).
    const R usq = R(1.5) * m.inv_eps * (m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);
    const R q2 = R(4.5) * m.inv_eps;
    [[maybe_unused]] const R src_p = R(1) - R(0.5) * op;
    [[maybe_unused]] const R src_m = R(1) - R(0.5) * om;
    [[maybe_unused]] const R uf =
        R(3) * m.inv_eps * (m.ux * force.fx + m.uy * force.fy + m.uz * force.fz);
    // Rest population: even only.
    R d0;
    if constexpr (kShifted<R>)
      d0 = op * (f[0] - R(kW[0]) * (m.drho - m.rho * usq));
    else
      d0 = op * (f[0] - kW[0] * m.rho * (1.0 - usq));
    if constexpr (kForced) d0 += src_p * R(kW[0]) * uf;
    f[0] -= d0;
    // Pairs (q, q + 1) with c_{q+1} = -c_q (d3q19.hpp).
    static_for<(kQ - 1) / 2>([&](auto kc) LBDEM_INLINE {
      constexpr int q = 2 * decltype(kc)::value + 1, o = q + 1;
      const R cu = dot_c<q>(m.ux, m.uy, m.uz);
      R eq_p;
      if constexpr (kShifted<R>)
        eq_p = R(kW[q]) * (m.drho + m.rho * (q2 * cu * cu - usq));
      else
        eq_p = kW[q] * m.rho * (1.0 + q2 * cu * cu - usq);
      const R eq_m = R(kW[q]) * m.rho * R(3) * cu;
      R dp = op * (R(0.5) * (f[q] + f[o]) - eq_p);
      R dm = om * (R(0.5) * (f[q] - f[o]) - eq_m);
      if constexpr (kForced) {
        const R cf = dot_c<q>(force.fx, force.fy, force.fz);
        dp -= src_p * R(kW[q]) * (R(2) * q2 * cu * cf - uf);
        dm -= src_m * R(kW[q]) * R(3) * cf;
      }
      f[q] -= dp + dm;
      f[o] -= dp - dm;
    });
  }
};

}  // namespace lbdem::lbm

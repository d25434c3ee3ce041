#pragma once
// BGK single-relaxation-time collision (Bhatnagar, Gross & Krook 1954; Qian et al. 1992):
//   f_q <- f_q - omega (f_q - f_q^eq) + (1 - omega/2) S_q,   omega = 1/tau,
// with Guo's source S_q (forcing/guo.hpp). Its wall location under bounce-back depends on tau
// (exact only at the magic combination (tau - 1/2)^2 = 3/16), so BGK is second order, not exact.
#include "lbm/cell.hpp"
#include "lbm/collision/collision_operator.hpp"
#include "lbm/d3q19.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace lbdem::lbm {

struct Bgk {
  static constexpr std::string_view name = "bgk";
  double omega;  // 1/tau [-], 0 < omega < 2

  static Bgk from_tau(double tau) {
    if (!(tau > 0.5))
      throw std::invalid_argument("BGK needs tau > 1/2, got " + std::to_string(tau));
    return {1.0 / tau};
  }
  double viscosity() const { return viscosity_from_tau(1.0 / omega); }

  // always_inline: see regularized_les.hpp (a call left in the omp simd cell loop runs scalar).
  // R: double on f_q, float on f_q - w_q (cell.hpp, kShifted), where the equilibrium is formed
  // shifted: w_q (drho + rho (3 c.u + ...)).
  template <bool kForced, class R>
  [[gnu::always_inline]] void relax(R (&f)[kQ], const CellMomentsT<R>& m,
                                    const CellForceT<R>& force) const {
    const R om = R(omega);
    // Terms of second order in u carry 1/eps (porous form, forcing/porous.hpp; 1 otherwise).
    const R usq = R(1.5) * (m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);  // u^2 / (2 c_s^2)
    const R q2 = R(4.5) * m.inv_eps;
    const R usq_e = usq * m.inv_eps;
    [[maybe_unused]] const R source = R(1) - R(0.5) * om;
    [[maybe_unused]] const R uf =
        R(3) * m.inv_eps * (m.ux * force.fx + m.uy * force.fy + m.uz * force.fz);
    static_for<kQ>([&](auto qc) LBDEM_INLINE {
      constexpr int q = decltype(qc)::value;
      const R cu = dot_c<q>(m.ux, m.uy, m.uz);
      R feq;
      if constexpr (kShifted<R>)
        feq = R(kW[q]) * (m.drho + m.rho * (R(3) * cu + q2 * cu * cu - usq_e));
      else
        feq = kW[q] * m.rho * (1.0 + 3.0 * cu + q2 * cu * cu - usq_e);
      R post = f[q] + om * (feq - f[q]);
      if constexpr (kForced) {
        const R cf = dot_c<q>(force.fx, force.fy, force.fz);
        post += source * R(kW[q]) * (R(3) * cf - uf + R(2) * q2 * cu * cf);
      }
      f[q] = post;
    });
  }
};

}  // namespace lbdem::lbm

#pragma once
// Dense/dilute switch of the two-fluid literature: Ergun in dense beds, Wen-Yu above eps = 0.8.
#include "coupling/drag/drag_law.hpp"
#include "coupling/drag/wen_yu.hpp"

#include <string_view>

namespace lbdem::coupling {

/// Ergun (1952, Chem. Eng. Prog. 48, 89) per particle:
///   beta_p = (pi d / 6) (150 mu (1-eps) / eps + 1.75 rho_f d |u|)   [kg/s],
/// the two-fluid beta = 150 (1-eps)^2 mu / (eps d^2) + 1.75 (1-eps) rho_f |u| / d (Gidaspow 1994)
/// times V_p / (1-eps). With U = eps |u|, the particles of a unit volume then carry
/// n (F_d - V_p grad p) = -grad p = 150 mu (1-eps)^2 U / (eps^3 d^2) + 1.75 (1-eps) rho_f U^2 /
/// (eps^3 d), Ergun's pressure drop, because F_d excludes the pressure-gradient part
/// (drag_law.hpp).
inline double ergun_coefficient(const DragInput& in, double slip_speed) {
  const double phi = 1 - in.eps;
  return kPi * in.d / 6 * (150 * in.mu * phi / in.eps + 1.75 * in.rho_f * in.d * slip_speed);
}

/// Gidaspow (1994, Multiphase Flow and Fluidization, Academic Press): Ergun for eps < 0.8,
/// Wen-Yu (wen_yu.hpp) for eps >= 0.8. Re of the Wen-Yu branch is rho_f eps |u| d / mu; the
/// Ergun branch needs none. The switch is discontinuous: in the viscous limit beta_p drops by
/// 13 % going up through eps = 0.8 (Wen-Yu 0.8^-3.65 = 2.26 against Ergun 30/11.52 = 2.60, in units
/// of 3 pi mu d U). Valid for packed to dilute beds, 0.35 <~ eps <= 1.
struct Gidaspow {
  static constexpr std::string_view name = "gidaspow";
  static constexpr bool uses_voidage = true;
  static constexpr double kSwitchVoidage = 0.8;

  double coefficient(const DragInput& in, double slip_speed) const {
    check_drag_input(name, in, slip_speed);
    if (in.eps >= kSwitchVoidage) return WenYu{}.coefficient(in, slip_speed);
    return ergun_coefficient(in, slip_speed);
  }
};

}  // namespace lbdem::coupling

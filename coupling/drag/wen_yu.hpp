#pragma once
// Single-sphere drag times a power-law voidage function.
#include "coupling/drag/drag_law.hpp"
#include "coupling/drag/schiller_naumann.hpp"

#include <cmath>
#include <string_view>

namespace lbdem::coupling {

/// Wen & Yu (1966, Chem. Eng. Prog. Symp. Ser. 62(62), 100), in the form of Gidaspow (1994,
/// Multiphase Flow and Fluidization):
///   F_d = C_D (pi d^2 / 8) rho_f U^2 eps^-3.65,  U = eps |u| (superficial),
///   C_D = 24/Re (1 + 0.15 Re^0.687) (Re < 1000), 0.44 above,  Re = rho_f eps |u| d / mu.
/// The exponent depends on where eps is counted: the two-fluid beta = 3/4 C_D eps (1-eps) rho_f
/// |u| / d eps^-2.65 (Gidaspow) is this law; per particle beta_p = 3 pi mu d (C_D Re/24) eps^-2.65;
/// in the superficial slip F_d ~ eps^-3.65; and the total force F_d / eps ~ eps^-4.65, Wen & Yu's
/// fitted eps^-4.7 (Richardson-Zaki n = 4.65 in the viscous limit). F_d excludes -V_p grad p.
/// Valid for dilute suspensions (Gidaspow uses it for eps >= 0.8); at eps = 0.4 it sits 9.3 %
/// below Ergun in the viscous regime.
struct WenYu {
  static constexpr std::string_view name = "wen_yu";
  static constexpr bool uses_voidage = true;
  static constexpr double kBetaExponent = -2.65;  // beta_p ~ eps^-2.65 (see above)

  double coefficient(const DragInput& in, double slip_speed) const {
    check_drag_input(name, in, slip_speed);
    const double re = particle_reynolds(in, in.eps * slip_speed);
    return stokes_coefficient(in) * schiller_naumann_factor(re) * std::pow(in.eps, kBetaExponent);
  }
};

}  // namespace lbdem::coupling

#pragma once
// Isolated sphere, standard drag curve below the drag crisis.
#include "coupling/drag/drag_law.hpp"

#include <cmath>
#include <string_view>

namespace lbdem::coupling {

/// C_D Re / 24 = F / (3 pi mu d w) of Schiller & Naumann (1933, Z. Ver. Dtsch. Ing. 77, 318):
/// C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, and the Newton-regime constant C_D = 0.44 above
/// (the extension Wen & Yu 1966 and Gidaspow 1994 use; the two branches meet within 0.4 %).
/// Written as C_D Re / 24 so that it stays finite at Re = 0.
inline double schiller_naumann_factor(double re) {
  return re < 1000 ? 1 + 0.15 * std::pow(re, 0.687) : 0.44 * re / 24;
}

/// Single sphere, F_d = 3 pi mu d u (1 + 0.15 Re^0.687), Re = rho_f |u| d / mu WITHOUT eps
/// (interstitial slip). eps is checked but not used: valid for dilute flow (eps -> 1, the jet
/// mill), Re < 2e5; the fit stays within about 5 % of the standard curve up to Re ~ 1000
/// (Clift, Grace & Weber 1978, Bubbles, Drops and Particles, ch. 5).
struct SchillerNaumann {
  static constexpr std::string_view name = "schiller_naumann";
  static constexpr bool uses_voidage = false;

  double coefficient(const DragInput& in, double slip_speed) const {
    check_drag_input(name, in, slip_speed);
    return stokes_coefficient(in) * schiller_naumann_factor(particle_reynolds(in, slip_speed));
  }
};

}  // namespace lbdem::coupling

#pragma once
// Isolated sphere, piecewise fit of the standard drag curve (the jet-mill law, docs/studies.md).
#include "coupling/drag/drag_law.hpp"

#include <array>
#include <string_view>

namespace lbdem::coupling {

/// One Reynolds range of Morsi & Alexander (1972, J. Fluid Mech. 55, 193, Table 1):
/// C_D = a1 + a2 / Re + a3 / Re^2 for Re below re_max.
struct MorsiAlexanderRange {
  double re_max;  // upper end of the range [-]
  double a1, a2, a3;
};

/// The published constants, 4-5 significant digits. Being rounded, adjacent ranges disagree at
/// their common end: by < 0.06 % up to Re = 100, -0.40 % at Re = 1000, +0.06 % at 5000 and
/// -2.3 % at 10^4 (tests/coupling/test_drag_laws.cpp measures them).
inline constexpr std::array<MorsiAlexanderRange, 8> kMorsiAlexanderRanges{{
    {0.1, 0.0, 24.0, 0.0},
    {1.0, 3.690, 22.73, 0.0903},
    {10.0, 1.222, 29.1667, -3.8889},
    {100.0, 0.6167, 46.50, -116.67},
    {1000.0, 0.3644, 98.33, -2778.0},
    {5000.0, 0.357, 148.62, -47500.0},
    {10000.0, 0.46, -490.546, 578700.0},
    {50000.0, 0.5191, -1662.5, 5416700.0},
}};

/// C_D Re / 24 of Morsi & Alexander; exactly 1 (Stokes) below Re = 0.1. Above Re = 5e4, the end
/// of the fit, the last range is continued (C_D = 0.50 at 1e5), short of the drag crisis.
inline double morsi_alexander_factor(double re) {
  if (re < kMorsiAlexanderRanges[0].re_max) return 1.0;
  for (const auto& r : kMorsiAlexanderRanges)
    if (re < r.re_max) return (r.a1 * re + r.a2 + r.a3 / re) / 24;
  const auto& r = kMorsiAlexanderRanges.back();
  return (r.a1 * re + r.a2 + r.a3 / re) / 24;
}

/// Single sphere, F_d = 3 pi mu d u (C_D Re / 24), Re = rho_f |u| d / mu WITHOUT eps
/// (interstitial slip), as in the spherical drag law of Fluent that the jet-mill study used.
/// eps is checked but not used: dilute flow only. Valid 0 < Re < 5e4.
struct MorsiAlexander {
  static constexpr std::string_view name = "morsi_alexander";
  static constexpr bool uses_voidage = false;

  double coefficient(const DragInput& in, double slip_speed) const {
    check_drag_input(name, in, slip_speed);
    return stokes_coefficient(in) * morsi_alexander_factor(particle_reynolds(in, slip_speed));
  }
};

}  // namespace lbdem::coupling

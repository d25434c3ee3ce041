#pragma once
// Drag fitted to lattice-Boltzmann simulations of random sphere arrays.
#include "coupling/drag/drag_law.hpp"

#include <cmath>
#include <string_view>

namespace lbdem::coupling {

/// Beetstra, van der Hoef & Kuipers (2007, AIChE J. 53, 489), monodisperse arrays, with
/// phi = 1 - eps and Re = rho_f eps |u| d / mu (superficial):
///   F = 10 phi / eps^2 + eps^2 (1 + 1.5 sqrt(phi))
///     + 0.413 Re / (24 eps^2) (1/eps + 3 eps phi + 8.4 Re^-0.343)
///                             / (1 + 10^(3 phi) Re^(-(1 + 4 phi)/2)),
/// F = F_d / (3 pi mu d U) the drag normalised by Stokes drag at the superficial slip. The third
/// term vanishes at Re = 0 (it behaves as Re^(1.157 + 2 phi)); it is taken as 0 there.
inline double beetstra_factor(double eps, double re) {
  const double phi = 1 - eps;
  const double viscous = 10 * phi / (eps * eps) + eps * eps * (1 + 1.5 * std::sqrt(phi));
  if (!(re > 0)) return viscous;
  const double num = 1 / eps + 3 * eps * phi + 8.4 * std::pow(re, -0.343);
  const double den = 1 + std::pow(10.0, 3 * phi) * std::pow(re, -(1 + 4 * phi) / 2);
  return viscous + 0.413 * re / (24 * eps * eps) * num / den;
}

/// Beetstra et al. (2007): F_d = 3 pi mu d U F(eps, Re), U = eps |u|, so beta_p = 3 pi mu d eps F.
/// F_d is the drag without the mean pressure-gradient force (van der Hoef et al. 2005: F_d = eps x
/// total force), so the coupling adds -V_p grad p. Fitted for 0.4 <= eps <= 0.9 and Re <= 1000;
/// F -> 1 (Stokes) as eps -> 1, Re -> 0; at eps = 1 and Re = 100 it is 16 % above
/// Schiller-Naumann (the dilute end is outside the data).
struct Beetstra {
  static constexpr std::string_view name = "beetstra";
  static constexpr bool uses_voidage = true;

  double coefficient(const DragInput& in, double slip_speed) const {
    check_drag_input(name, in, slip_speed);
    const double re = particle_reynolds(in, in.eps * slip_speed);
    return stokes_coefficient(in) * in.eps * beetstra_factor(in.eps, re);
  }
};

}  // namespace lbdem::coupling

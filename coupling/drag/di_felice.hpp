#pragma once
// Single-sphere drag times a Reynolds-dependent voidage function.
#include "coupling/drag/drag_law.hpp"

#include <cmath>
#include <string_view>

namespace lbdem::coupling {

/// Di Felice (1994, Int. J. Multiphase Flow 20, 153) voidage exponent,
/// chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2): 3.7 in both the viscous and the inertial
/// limit, minimum 3.05 at Re = 10^1.5. Returns 3.7 at Re = 0.
inline double di_felice_chi(double re) {
  if (!(re > 0)) return 3.7;
  const double x = 1.5 - std::log10(re);
  return 3.7 - 0.65 * std::exp(-0.5 * x * x);
}

/// C_D Re / 24 of Dallavalle's (1948, Micromeritics) C_D = (0.63 + 4.8 / sqrt(Re))^2, the
/// single-sphere curve Di Felice used. Note it tends to 4.8^2/24 = 0.96 of Stokes as Re -> 0.
inline double dallavalle_factor(double re) {
  const double s = 0.63 * std::sqrt(re) + 4.8;
  return s * s / 24;
}

/// Di Felice (1994), in the CFD-DEM form of Xu & Yu (1997, Chem. Eng. Sci. 52, 2785):
///   F_d = C_D (pi d^2 / 8) rho_f U^2 eps^-chi(Re),  U = eps |u| (superficial),
///   Re = rho_f eps |u| d / mu,  so beta_p = 3 pi mu d (C_D Re/24) eps^(1-chi).
/// F_d excludes -V_p grad p (Zhou et al. 2010, model A): with it, a homogeneous suspension settles
/// at eps^(chi+1) (viscous) or eps^((chi+1)/2) (inertial) of the single-particle velocity, close to
/// Richardson-Zaki's 4.65 and 2.39, which is what chi was fitted to. Valid 1e-2 < Re < 1e4
/// over the voidage of fixed and fluidized beds, eps >~ 0.4.
struct DiFelice {
  static constexpr std::string_view name = "di_felice";
  static constexpr bool uses_voidage = true;

  double coefficient(const DragInput& in, double slip_speed) const {
    check_drag_input(name, in, slip_speed);
    const double re = particle_reynolds(in, in.eps * slip_speed);
    return stokes_coefficient(in) * dallavalle_factor(re) * std::pow(in.eps, 1 - di_felice_chi(re));
  }
};

}  // namespace lbdem::coupling

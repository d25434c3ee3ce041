#pragma once
// The drag-law contract of the unresolved coupling (docs/physics.md, Drag laws): one value type per
// law, one header per law beside this one, the run-time choice in drag_model.hpp.
//
// Conventions shared by every law here:
//  - Velocities. The caller passes the INTERSTITIAL slip u = u_f - u_p (u_f the local gas velocity,
//    not the superficial eps u_f). Laws fitted to the superficial slip U = eps |u| form it
//    themselves; each law states the Reynolds number it uses (Re_p with or without eps).
//  - Output. coefficient() returns the momentum-exchange coefficient of ONE particle,
//    beta_p [kg/s], with F_d = beta_p (u_f - u_p) the drag on that particle [N];
//    drag_force() multiplies it out. The per-volume beta of two-fluid models is beta_p (1-eps)/V_p.
//  - Split of the fluid force (Zhou, Kuang, Chu & Yu 2010, J. Fluid Mech. 661, 482: model A,
//    their "set II"). F_d EXCLUDES the pressure-gradient (buoyancy) part; the coupling adds
//    F_gradp = -V_p grad p itself (pressure_gradient_force below), so the total fluid force is
//    F_d - V_p grad p. In a uniform steady bed -grad p = n (F_d - V_p grad p) with n V_p = 1 - eps,
//    so F_d = eps x (total force); that is van der Hoef, Beetstra & Kuipers (2005, J. Fluid Mech.
//    528, 233) "F_d = eps F", the reading under which Ergun, Wen-Yu, Di Felice and Beetstra are
//    written here. Model B ("set I") uses the total force F_d / eps instead.
//  - Voidage functions. In the superficial slip U = eps |u|, F_d = F_single(U, Re(U)) eps^-chi,
//    with chi = 3.65 (Wen-Yu) or chi(Re) (Di Felice), F_single the isolated-sphere drag; hence
//    beta_p = 3 pi mu d (C_D Re/24) eps^(1-chi). Each law writes its exponent in these terms.
//
// Adding a law: one header with a struct like SchillerNaumann (name, uses_voidage, coefficient),
// one more alternative in drag_model.hpp, one test of its reference values.
#include "core/error.hpp"
#include "core/types.hpp"

#include <cmath>
#include <concepts>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lbdem::coupling {

/// Local state one drag evaluation sees, in SI. d is the diameter the law uses: for a
/// coarse-grained parcel that is the ORIGINAL particle's diameter (coarse_grain_drag.hpp).
struct DragInput {
  double rho_f;  // gas density [kg/m^3]
  double mu;     // gas dynamic viscosity [Pa s]
  double eps;    // fluid fraction (voidage) at the particle, 0 < eps <= 1 [-]
  double d;      // sphere diameter [m]
};

/// rho_f w d / mu for a slip speed w [-]. Which speed (interstitial |u| or superficial eps |u|)
/// is part of each law's definition.
inline double particle_reynolds(const DragInput& in, double w) {
  return in.rho_f * w * in.d / in.mu;
}

/// Stokes drag coefficient of an isolated sphere, 3 pi mu d [kg/s] (creeping flow, F = 3 pi mu d
/// u).
inline double stokes_coefficient(const DragInput& in) {
  return 3 * kPi * in.mu * in.d;
}

/// Rejects states outside every law's domain: eps in (0, 1], d, mu, rho_f > 0, finite slip speed.
/// std::invalid_argument naming the law, the quantity and the value.
inline void check_drag_input(std::string_view law, const DragInput& in, double slip_speed) {
  auto fail = [&](const char* what, double v, const char* need) {
    throw std::invalid_argument(std::string(law) + " drag: " + what + " = " + to_text(v) +
                                " is out of range; it must be " + need);
  };
  if (!(in.eps > 0 && in.eps <= 1)) fail("fluid fraction eps", in.eps, "in (0, 1]");
  if (!(in.d > 0 && std::isfinite(in.d))) fail("particle diameter d", in.d, "> 0 [m]");
  if (!(in.mu > 0 && std::isfinite(in.mu))) fail("gas viscosity mu", in.mu, "> 0 [Pa s]");
  if (!(in.rho_f > 0 && std::isfinite(in.rho_f)))
    fail("gas density rho_f", in.rho_f, "> 0 [kg/m^3]");
  if (!(slip_speed >= 0 && std::isfinite(slip_speed)))
    fail("slip speed |u_f - u_p|", slip_speed, "finite [m/s]");
}

/// What the coupling needs from a drag law (the collision_operator.hpp pattern as a concept).
/// uses_voidage is false for single-sphere laws, which ignore eps (a driver may warn when they
/// meet a dense region).
template <class L>
concept DragLaw = std::copyable<L> &&
    requires(const L& law, const DragInput& in, double slip_speed) {
  { L::name } -> std::convertible_to<std::string_view>;
  { L::uses_voidage } -> std::convertible_to<bool>;
  /// beta_p [kg/s] for the interstitial slip speed |u_f - u_p|; throws std::invalid_argument.
  { law.coefficient(in, slip_speed) } -> std::convertible_to<double>;
};

/// Drag on one particle, F_d = beta_p (u_f - u_p) [N]; slip = u_f - u_p, interstitial [m/s].
template <DragLaw L>
Vec3 drag_force(const L& law, const DragInput& in, const Vec3& slip) {
  return law.coefficient(in, slip.norm()) * slip;
}

/// The pressure-gradient force the laws leave out, -V_p grad p with V_p = pi d^3 / 6 [N]
/// (Zhou et al. 2010, model A). For a parcel, d is the parcel diameter: it displaces its volume.
inline Vec3 pressure_gradient_force(double d, const Vec3& grad_p) {
  return -(kPi * d * d * d / 6) * grad_p;
}

}  // namespace lbdem::coupling

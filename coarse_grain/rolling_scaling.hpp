#pragma once
// Rolling resistance under coarse graining (dem/contact/rolling_resistance.hpp; Ai, Chen, Rotter &
// Ooi 2011, Powder Technol. 206:269). Both models take mu_r and the arm r_arm = a R* with a fixed
// factor a, so the parcel keeps mu_r and a under every rule and nothing else is set:
//  - constant torque (model A): M = mu_r a R* F_n. R* -> l R*, so M/F_n ~ l: the torque scales
//    with the contact force like every other lever arm. A sphere rolling on a plane at v0 stops
//    after s = 7 v0^2 / (10 mu_r g a), independent of the size: the parcel keeps it.
//  - EPSD (model C without the viscous part): k_r = 2.25 k_n mu_r^2 r_arm^2 (Ai et al. 2011,
//    eq. 16, with the engine's current normal stiffness k_n: the linear k or the Hertz secant
//    4/3 E* sqrt(R* delta)). With k_n -> l k_n and r_arm -> l r_arm, k_r -> l^3 k_r, so the rolling
//    period 2 pi sqrt(I*/k_r) (I* ~ l^5) scales as l like t_c, and the rotation at full
//    mobilisation theta_m = mu_r r_arm F_n / k_r = F_n / (2.25 k_n mu_r r_arm) = delta /
//    (2.25 mu_r r_arm) is kept wherever delta/d is. This holds for all three contact rules, since
//    each scales k_n (or its Hertz secant at the same delta/d) by l.
namespace lbdem::cg {

/// EPSD rolling stiffness as the engine computes it [N m/rad].
inline double epsd_rolling_stiffness(double k_n, double mu_r, double r_arm) {
  return 2.25 * k_n * mu_r * mu_r * r_arm * r_arm;
}

/// Rolling rotation at which the EPSD spring reaches its limit torque mu_r r_arm k_n delta [rad].
inline double epsd_mobilisation_angle(double delta, double mu_r, double r_arm) {
  return delta / (2.25 * mu_r * r_arm);
}

/// k_r,cg / k_r: k_n ratio (l under every rule) times the arm ratio squared (l^2).
inline double epsd_stiffness_factor(double l) {
  return l * l * l;
}

}  // namespace lbdem::cg

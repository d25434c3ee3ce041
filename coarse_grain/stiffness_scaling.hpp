#pragma once
// Normal-contact scaling rules: parcel stiffness, damping and time step from the original material
// and the size factor l (radius R -> l R, density kept, mass m -> l^3 m).
//
// Linear spring-dashpot F = k delta + gamma v_n between two equal particles of mass m (m* = m/2):
//   omega_0 = sqrt(k/m*), zeta = gamma / (2 sqrt(m* k)),
//   t_c = pi / (omega_0 sqrt(1 - zeta^2)), e = exp(-pi zeta / sqrt(1 - zeta^2)),
//   delta_max = (v/omega_0) f(zeta)  (impact speed v; f depends on zeta alone)
// (closed form of the damped oscillator; Schaefer, Dippel & Wolf 1996, J. Phys. I 6:5).
// With m* -> l^3 m* the rules below follow.
//
// stiffness_only (the rheometer seed, k_cg = l k, with the damping coefficient read as
// the absolute gamma): omega_0 -> omega_0 / l, zeta -> zeta / l^2, so e drifts up with l
// (e = 0.8: 0.9167 at l = 1.6, 0.9459 at l = 2, 0.9862 at l = 4) and t_c -> l t_c sqrt(1 -
// zeta^2) / sqrt(1 - zeta^2/l^4), within 0.3 % of l t_c for e = 0.8. The engine's linear law
// takes e, not gamma (dem/contact/linear_spring_dashpot.hpp), so the parcel's damping is given as
// the restitution of zeta / l^2 as well as the absolute gamma. The two are equivalent for an
// equal-parcel pair, and for any pair (unequal parcels, parcel-wall) whose original gamma was
// itself set from e, because every m* scales by l^3 and zeta / l^2 does not depend on m*.
//
// linear_similarity (Bierwisch, Kraft, Riedel & Moseler 2009, J. Mech. Phys. Solids 57:10, energy
// similarity; Radl, Radeke, Khinast & Sundaresan 2011): k -> l k and gamma -> l^2 gamma keep zeta,
// hence e and delta_max/d (delta_max proportional to v sqrt(m*/k) ~ l); t_c -> l t_c, so the step
// dt -> l dt keeps the steps per contact. Every term of m* x'' = -k x - gamma x' scales as l^2
// when x ~ l and t ~ l: a collision of parcels is the original one magnified. Not kept: the
// static overlap under the parcel's own weight, delta/d = m g/(k d) ~ l (a bed of fixed depth
// keeps it: its contact forces scale as the stress times d^2, i.e. l^2).
//
// hertz (Hertz 1882, Johnson 1985 eq. 4.23, with Tsuji et al. 1992 damping, E and nu unchanged):
// F = 4/3 E* sqrt(R*) delta^{3/2} is l^2 F at delta -> l delta, so contact stress and strain are
// kept; delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5} ~ l, t_c = 2.868 (m*^2 / (R* E*^2
// v))^{1/5} ~ l, and Tsuji damping gives an e independent of size (Thakur, Ooi & Ahmadian 2016,
// Powder Technol. 293:130, found Hertz-Mindlin bulk behaviour scale-invariant this way). Under its
// own weight a parcel's static delta/d grows as l^{2/3} ((delta/d)^{3/2} ~ m g / (E* d^2) ~ l); in
// a bed of given depth (contact force ~ stress d^2 ~ l^2) it is kept.
#include "dem/material.hpp"

namespace lbdem::cg {

/// e = exp(-pi zeta / sqrt(1 - zeta^2)) for zeta < 1; 0 at and above critical damping.
double linear_restitution(double zeta);
/// Its inverse, zeta = |ln e| / sqrt(ln^2 e + pi^2) (= |beta(e)| of dem/contact/restitution.hpp).
double linear_damping_ratio(double e);

/// Normal-contact parameters of a parcel under one rule.
struct NormalContact {
  double stiffness;         // linear k_n [N/m] (unchanged and unused under hertz)
  double youngs_modulus;    // E [Pa] (unchanged and unused under the linear rules)
  double restitution;       // e to give the engine: equal-parcel pair [-]
  double damping;           // absolute gamma of an equal-parcel pair [N s/m]; 0 under hertz,
                            // where gamma = sqrt5 |beta| sqrt(m* k_n(delta)) varies in the contact
  double time_step_factor;  // t_c,cg / t_c = dt_cg / dt at the same steps per contact [-]
};

/// Each rule maps (original material, original radius [m], size factor l >= 1) to the parcel's
/// normal contact; l = 1 returns the original.
NormalContact stiffness_only(const dem::Material& m, double radius, double l);
NormalContact linear_similarity(const dem::Material& m, double radius, double l);
NormalContact hertz(const dem::Material& m, double radius, double l);

}  // namespace lbdem::cg

#pragma once
// Cohesion scaling: the Hamaker constant of a parcel.
//
// Van der Waals between spheres, F = A R* / (6 h^2) (Hamaker 1937; dem/contact/van_der_waals.hpp),
// with the gap h, h_min and h_max kept ABSOLUTE: they are molecular and surface-roughness lengths,
// not multiples of the diameter. At a given h, R* -> l R* alone makes F_cg = l F. A target F_cg =
// l^p F therefore needs A_cg R*_cg = l^p A R*, i.e.
//   A_cg = l^(p-1) A:
//   - tensile_strength, p = 2: A_cg = l A. The bulk tensile strength of a packing scales as (force
//     per contact) x (contacts per area ~ 1/d^2), so F ~ d^2 keeps it (Thakur, Ooi & Ahmadian 2016,
//     Powder Technol. 293:130; Rumpf's sigma_t ~ F/d^2).
//   - bond_number, p = 3: A_cg = l^2 A. Bo = F/(m g) with m ~ l^3 is kept, and so is the cohesive
//     energy per unit mass, the CG model's energy balance (one parcel carries the energy of l^3
//     originals; Sakai & Koshizuka 2009, Sakai et al. 2012, Adv. Powder Technol. 23:673).
//   - unscaled, p = 1: A_cg = A, a baseline that keeps neither (Bo ~ 1/l^2, sigma_t ~ 1/l).
// The potential U = -A R*/6 (1/h - 1/h_max) scales with the same factor as F, since h is absolute.
#include <cmath>

#include "coarse_grain/scaling_rule.hpp"

namespace lbdem::cg {

/// p of F_cg = l^p F at the same gap.
inline int cohesion_force_exponent(CohesionRule r) {
  switch (r) {
    case CohesionRule::tensile_strength:
      return 2;
    case CohesionRule::bond_number:
      return 3;
    case CohesionRule::unscaled:
      return 1;
  }
  return 1;
}

/// A_cg = l^(p-1) A [J].
inline double scaled_hamaker(double hamaker, double l, CohesionRule r) {
  return hamaker * std::pow(l, cohesion_force_exponent(r) - 1);
}

}  // namespace lbdem::cg

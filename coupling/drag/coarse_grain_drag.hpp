#pragma once
// Drag on a coarse-grained parcel (docs/physics.md, Drag laws; coarse_grain/drag_scaling.hpp): the
// parcel carries l^3 originals, each dragged as an original at the same eps and slip, so F_parcel =
// l^3 F_d(d_parcel / l). The parcel's drag per unit mass, hence its relaxation time and terminal
// velocity, is the original's (Sakai & Koshizuka 2009, Chem. Eng. Sci. 64, 533).
#include "coarse_grain/drag_scaling.hpp"
#include "core/error.hpp"
#include "coupling/drag/drag_law.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lbdem::coupling {

/// beta_p of a parcel of diameter parcel.d and size factor l >= 1 [kg/s]; eps, rho_f and mu are the
/// gas state at the parcel.
template <DragLaw L>
double parcel_drag_coefficient(const L& law, const DragInput& parcel, double size_factor,
                               double slip_speed) {
  if (!(size_factor >= 1 && std::isfinite(size_factor)))
    throw std::invalid_argument(std::string(L::name) + " parcel drag: size factor l = " +
                                to_text(size_factor) + " is out of range; it must be >= 1");
  const cg::DragScaling s = cg::drag_scaling(parcel.d, size_factor);
  DragInput original = parcel;
  original.d = s.original_diameter;
  return s.factor * law.coefficient(original, slip_speed);
}

/// F_parcel = l^3 F_d(one original of diameter parcel.d / l) [N]; slip = u_f - u_p [m/s].
template <DragLaw L>
Vec3 parcel_drag_force(const L& law, const DragInput& parcel, double size_factor,
                       const Vec3& slip) {
  return parcel_drag_coefficient(law, parcel, size_factor, slip.norm()) * slip;
}

}  // namespace lbdem::coupling

#pragma once
// What the stream-collide kernel needs from a collision operator (waLBerla's prose "lattice model"
// contract, as a C++20 concept). An operator is a small value type holding its rates; its relax()
// takes the 19 pre-collision populations of one cell, their moments (u already Guo-shifted) and the
// cell's force, and overwrites f with the post-collision populations including the forcing source,
// in double on f_q and in float on f_q - w_q (cell.hpp).
// relax<false> must not read the force: the kernel passes zeros and relies on the terms vanishing.
//
// A new operator (regularized or MRT with a Smagorinsky eddy viscosity) is one more
// header beside bgk.hpp and trt.hpp and one more alternative in collision_model.hpp: the LES
// variant computes its local omega from the non-equilibrium stress of f inside relax().
#include "lbm/cell.hpp"
#include "lbm/d3q19.hpp"

#include <concepts>
#include <string_view>

namespace lbdem::lbm {

template <class C>
concept CollisionOperator = std::copyable<C> &&
    requires(const C& c, double (&f)[kQ], const CellMoments& m, const CellForce& force,
             float (&fs)[kQ], const CellMomentsT<float>& ms, const CellForceT<float>& forces) {
  { C::name } -> std::convertible_to<std::string_view>;
  c.template relax<false>(f, m, force);
  c.template relax<true>(f, m, force);
  // Single precision: shifted populations f_q - w_q (cell.hpp, kShifted).
  c.template relax<false>(fs, ms, forces);
  c.template relax<true>(fs, ms, forces);
  /// Kinematic shear viscosity [lattice units], nu = c_s^2 (1/omega_+ - 1/2).
  { c.viscosity() } -> std::convertible_to<double>;
};

/// nu = c_s^2 (tau - 1/2) (shear viscosity of the second-order Chapman-Enskog expansion).
inline double viscosity_from_tau(double tau) {
  return kCs2 * (tau - 0.5);
}
inline double tau_from_viscosity(double nu) {
  return nu / kCs2 + 0.5;
}

}  // namespace lbdem::lbm

#pragma once
// A forcing-policy wrapper that records, per storage cell, the density and the intrinsic velocity
// u / eps each collision relaxed towards (the step's velocity, half-force shift and porous drag
// included), for boundary conditions that need a wall cell's moments after the step
// (boundary/wall_function.hpp). They then read four values per cell instead of the cell's 19
// populations from 19 arrays: on the jet mill those scattered loads cost more than the collision
// itself (the wall function took 58 % of a gas run, the collision 41 %; perf put the time on the
// loads). The stores are unconditional, so the cell loop stays vectorised.
#include "core/types.hpp"
#include "lbm/cell.hpp"
#include "lbm/d3q19.hpp"

namespace lbdem::lbm {

/// Per storage cell: rho and u / eps of the last collision, in the lattice's precision S.
template <class S>
struct MomentFields {
  S* rho;
  S* u[3];
};

template <class Base, class S>
struct StoreMoments {
  static constexpr bool kActive = Base::kActive;
  Base base;
  MomentFields<S> out;

  template <class R>
  [[gnu::always_inline]] CellMomentsT<R> moments(const R (&f)[kQ], Index n,
                                                 CellForceT<R>& force) const {
    const CellMomentsT<R> m = base.moments(f, n, force);
    out.rho[n] = S(m.rho);
    out.u[0][n] = S(m.ux * m.inv_eps);
    out.u[1][n] = S(m.uy * m.inv_eps);
    out.u[2][n] = S(m.uz * m.inv_eps);
    return m;
  }
};

}  // namespace lbdem::lbm

#pragma once
// A mass source m added to a cell as resting equilibrium populations, f_q += w_q m
// (LbmSolver::set_mass_source_field: the coupling's displaced gas). The solver adds a step's
// sources to the populations the next step reads; where it can, it does so inside that step's
// collision as the cell's populations are loaded (WithMassSource) instead of in a pass of its own,
// which read and wrote every source cell's 19 slots once more per step: on the jet mill's CG-10
// run with its bed in, that pass took 20 % of the run even in vector lanes (perf, 1 thread). One
// helper does the arithmetic wherever the sources are added, so that every path gives the same
// bits.
#include "core/types.hpp"
#include "lbm/cell.hpp"
#include "lbm/d3q19.hpp"

#include <cmath>

namespace lbdem::lbm {

/// Slot `slot` of direction q with w_q m added, in the slot's precision. On shifted float slots
/// (f_q - w_q, pdf_field.hpp) the sum is the same as on f_q. m = 0 leaves the slot's value as it
/// is (a slot of -0 turns +0). A fused multiply-add written out where the machine has one: left
/// to the compiler, the product was contracted into the sum in some inlined copies and not in
/// others, and the outlet's sample of a pending source differed from the pass's in the last bit.
template <class T>
[[gnu::always_inline]] inline T with_mass(T slot, int q, T m) {
#if defined(__FMA__)
  return std::fma(T(kW[q]), m, slot);
#else
  return slot + T(kW[q]) * m;
#endif
}

/// A forcing policy that adds the pending mass sources to each cell's populations as the collision
/// loads them (stream_collide.hpp, collide_cell), then defers to Base.
template <class Base>
struct WithMassSource {
  static constexpr bool kActive = Base::kActive;
  Base base;
  const double* mass;  // per storage cell, mass per step [lattice units]; 0: none

  template <class T>
  [[gnu::always_inline]] void add_mass(T (&f)[kQ], Index n) const {
    const T m = T(mass[n]);
    // Unrolled (static_for): a loop over q would index f at run time and keep the cell loop
    // from vectorising.
    static_for<kQ>([&](auto q) LBDEM_INLINE { f[q] = with_mass(f[q], int(q), m); });
  }
  template <class R>
  [[gnu::always_inline]] CellMomentsT<R> moments(const R (&f)[kQ], Index n,
                                                 CellForceT<R>& force) const {
    return base.moments(f, n, force);
  }
};

}  // namespace lbdem::lbm

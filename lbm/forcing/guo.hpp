#pragma once
// Guo forcing (Guo, Zheng & Shi 2002, Phys. Rev. E 65, 046308, eqs. 19-20): the source added in the
// collision is (1 - omega/2) S_q with
//   S_q = w_q [ (c_q - u)/c_s^2 + (c_q.u) c_q / c_s^4 ] . F,
// and the velocity is u = (sum_q c_q f_q + F/2) / rho (cell.hpp). This recovers the Navier-Stokes
// force term without the O(dt) discrete-lattice errors of a plain c_q.F source. For TRT the source
// is split into its even and odd parts in c_q, relaxed with omega+ and omega- respectively
// (trt.hpp):
//   S_q^+ = w_q [ (c_q.u)(c_q.F)/c_s^4 - u.F/c_s^2 ],   S_q^- = w_q (c_q.F)/c_s^2.
//
// Forcing policies give the kernel the moments of a cell and the force its source term uses
// (moments(f, n, force)); kActive = false compiles the terms out. forcing/porous.hpp adds the
// porous-medium policy.
#include "core/types.hpp"
#include "lbm/cell.hpp"
#include "lbm/d3q19.hpp"

namespace lbdem::lbm {

/// No force: the kernel's forcing terms vanish at compile time.
struct NoForce {
  static constexpr bool kActive = false;
  template <class R>
  [[gnu::always_inline]] CellMomentsT<R> moments(const R (&f)[kQ], Index,
                                                 CellForceT<R>& force) const {
    force = {};
    return cell_moments<false>(f, force);
  }
};

/// The same force density in every cell (gravity on the gas, a pressure-gradient surrogate).
struct UniformForce {
  static constexpr bool kActive = true;
  CellForce force;
  CellForce at(Index) const { return force; }
  template <class R>
  [[gnu::always_inline]] CellMomentsT<R> moments(const R (&f)[kQ], Index,
                                                 CellForceT<R>& out) const {
    out = {R(force.fx), R(force.fy), R(force.fz)};
    return cell_moments<true>(f, out);
  }
};

/// A per-cell force density (SoA over storage cells, e.g. the reaction of particle drag) in the
/// lattice's precision S, plus a uniform part.
template <class S>
struct FieldForce {
  static constexpr bool kActive = true;
  const S* fx;
  const S* fy;
  const S* fz;
  CellForce uniform;
  template <class R>
  [[gnu::always_inline]] CellForceT<R> force_at(Index n) const {
    return {R(uniform.fx) + R(fx[n]), R(uniform.fy) + R(fy[n]), R(uniform.fz) + R(fz[n])};
  }
  template <class R>
  [[gnu::always_inline]] CellMomentsT<R> moments(const R (&f)[kQ], Index n,
                                                 CellForceT<R>& out) const {
    out = force_at<R>(n);
    return cell_moments<true>(f, out);
  }
};
template <class S>
FieldForce(const S*, const S*, const S*, CellForce) -> FieldForce<S>;

}  // namespace lbdem::lbm

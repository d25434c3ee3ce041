#pragma once
// Porous-medium (volume-averaged) form for unresolved coupling: the generalized lattice Boltzmann
// model of Guo & Zhao (2002, Phys. Rev. E 66, 036304), for the superficial velocity u of a medium
// of fluid fraction eps and permeability K:
//   div u = 0,
//   du/dt + (u.grad)(u/eps) = -(1/rho) grad(eps p) + nu_e lap u + F,                   (GZ eq. 1)
//   F = -(eps nu / K) u - (eps F_eps / sqrt K) |u| u + G.                               (GZ eq. 2)
// (GZ write eps G for the body acceleration; here G is the applied force density as given, so a
// caller that wants eps G passes it scaled: the reaction of particle drag is not scaled by eps.)
// On the lattice (GZ eqs. 11-16, dt = 1):
//   f_q^eq = w_q rho [1 + c.u/c_s^2 + (c.u)^2/(2 eps c_s^4) - u^2/(2 eps c_s^2)],
//   S_q    = w_q (1 - omega/2) [c.F/c_s^2 + (u F : (c c - c_s^2 I))/(eps c_s^4)],
//   rho = sum f_q,  u = v / (c0 + sqrt(c0^2 + c1 |v|)),  v = (sum c_q f_q + G/2) / rho,
//   c0 = (1 + alpha/(2 rho))/2,  c1 = beta/2,  F = G - (alpha + rho beta |u|) u,
// i.e. the linear (Darcy) and quadratic (Forchheimer) drag are taken at the new velocity
// (semi-implicit), which keeps a stiff drag (alpha >> rho, a packed bed) stable. alpha is the
// Darcy drag per unit volume and velocity, mu eps / K in lattice units (GZ's rho eps nu / K; the
// two agree at rho = 1): a drag coefficient rather than a rate, so that a caller that sets it from
// particle drag (coupling/) knows the force the gas feels exactly, whatever rho does. The
// operators apply 1/eps through CellMoments::inv_eps; this policy supplies it, u and the total
// force F.
// Left out, as in GZ: d(eps)/dt in the mass balance (eps is frozen during a step, so a moving bed
// does not displace gas by itself), the grad(eps) terms of the averaged viscous stress (nu_e lap u
// on the superficial velocity). The pressure term is -grad(rho c_s^2): GZ read rho c_s^2 as eps p,
// so that a quiescent gas across a step in eps stays at rest with uniform rho; the fluid-particle
// coupling reads it as the gas pressure p itself and passes the rest of the averaged pressure
// term, (1 - eps) grad p, through the particles (coupling/coupler.hpp).
#include "core/types.hpp"
#include "lbm/cell.hpp"
#include "lbm/d3q19.hpp"

#include <cmath>

namespace lbdem::lbm {

/// Base: the applied-force policy (guo.hpp: UniformForce or FieldForce). S: the precision of the
/// per-cell fields (the lattice's). kSum: add to the velocity
/// sums; a compile-time choice, since a store under a run-time test kept GCC 12 from vectorising
/// the cell loop (14 against 42 MLUPS, bench/lbm_bench --porous). kForchheimer = false drops the
/// two square roots of |u| and of the quadratic's root (beta = 0 gives scale = 1 / (2 c0)
/// exactly): the solver chooses it where beta = 0, which the coupling always has (cell.hpp: the
/// divisions and roots of this kernel).
template <class S, class Base, bool kSum = false, bool kForchheimer = true>
struct PorousMedium {
  static constexpr bool kActive = true;
  Base applied;
  const S* inv_eps;  // 1 / fluid fraction per storage cell, >= 1 (stored: no division)
  const S* alpha;    // Darcy drag mu eps / K per storage cell [lattice units], >= 0
  double beta = 0;   // Forchheimer coefficient eps F_eps / sqrt(K) [1/cell], >= 0
  // With kSum, sums of the intrinsic velocity u / eps per storage cell (x, y, z), added to by every
  // collision that uses this policy (LbmSolver::enable_velocity_sum): the coupling's record of the
  // velocities the gas's drag acted on, without a second pass over the populations.
  S* u_sum[3] = {nullptr, nullptr, nullptr};

  template <class R>
  [[gnu::always_inline]] CellMomentsT<R> moments(const R (&f)[kQ], Index n,
                                                 CellForceT<R>& force) const {
    CellForceT<R> g;
    CellMomentsT<R> m = applied.moments(f, n, g);  // u = v here
    const R a = R(alpha[n]) * m.inv_rho;           // GZ's rate eps nu / K
    const R c0 = R(0.5) * (R(1) + R(0.5) * a);
    R scale, rate;  // rate: alpha + beta |u| over rho
    if constexpr (kForchheimer) {
      const R v = std::sqrt(m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);
      scale = R(1) / (c0 + std::sqrt(c0 * c0 + R(0.5) * R(beta) * v));
      rate = a + R(beta) * v * scale;
    } else {
      scale = R(1) / (R(2) * c0);
      rate = a;
    }
    m.ux *= scale;
    m.uy *= scale;
    m.uz *= scale;
    m.inv_eps = R(inv_eps[n]);
    if constexpr (kSum) {
      u_sum[0][n] += S(m.ux * m.inv_eps);
      u_sum[1][n] += S(m.uy * m.inv_eps);
      u_sum[2][n] += S(m.uz * m.inv_eps);
    }
    const R drag = m.rho * rate;  // rho (alpha + beta |u|)
    force = {g.fx - drag * m.ux, g.fy - drag * m.uy, g.fz - drag * m.uz};
    return m;
  }
};

}  // namespace lbdem::lbm

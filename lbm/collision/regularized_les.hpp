#pragma once
// Regularized BGK (Latt & Chopard 2006, Math. Comput. Simul. 72, 165) with a Smagorinsky eddy
// viscosity taken locally from the non-equilibrium stress (Hou, Sterling, Chen & Doolen 1996,
// Fields Inst. Commun. 6, 151; Malaspinas & Sagaut 2012, J. Fluid Mech. 700, 514): the
// stable LES operator for the jet mill (docs/physics.md, Collision operators and LES).
//
// Collision, with Q_q = c_q c_q - c_s^2 I and Pi = sum_q c_q c_q (f_q - f_q^eq):
//   f_q <- f_q^eq + (1 - omega) w_q [c_q.(j - rho u)/c_s^2 + Q_q : Pi / (2 c_s^4)]
//          + (1 - omega/2) S_q,
// i.e. f^neq is replaced by its Hermite projection up to second order, which drops the ghost
// moments that make BGK blow up when tau -> 1/2 (j - rho u = -F/2 with Guo's shifted u).
// Mass, momentum and the second moment relax exactly as in BGK with Guo forcing (S_q:
// forcing/guo.hpp), so the Chapman-Enskog result is BGK's.
//
// Eddy viscosity. Chapman-Enskog with Guo forcing (Guo, Zheng & Shi 2002, Phys. Rev. E 65,
// 046308) gives f^(1) = -tau D_0 f^eq + (tau - 1/2) S, whose second moment is
//   Pi = -2 tau rho c_s^2 S_ab - (u_a F_b + F_a u_b)/2,
// so the strain is read from Pi^c = Pi + (u F + F u)/2 (plus sign: the force part of Pi is
// -(u F + F u)/2 and must be removed). With the porous equilibrium of Guo & Zhao
// 2002 (Phys. Rev. E 66, 036304) both u u and the u F source moment carry 1/eps, and so does the
// correction. Smagorinsky: nu_t = (C_s Delta)^2 |S|, |S| = sqrt(2 S:S), Delta = dx = 1, and
// tau = tau0 + nu_t / c_s^2. Using the local tau in Pi^c = -2 tau rho c_s^2 S gives
// |S| = |Pi^c| / (sqrt 2 rho c_s^2 tau), |Pi^c| = sqrt(Pi^c : Pi^c), hence the quadratic
// tau^2 - tau0 tau - 9 C_s^2 |Pi^c| / (sqrt 2 rho) = 0 with the positive root
//   tau = ( tau0 + sqrt(tau0^2 + 18 sqrt(2) C_s^2 |Pi^c| / rho) ) / 2       (Hou et al. 1996).
// C_s = 0 gives tau = tau0 exactly: plain regularized BGK.
//
// Porosity: CellMoments::inv_eps multiplies the terms of second order in u of f^eq (and of its
// second moment, rho u u) and of the Guo source (Guo & Zhao 2002).
#include "lbm/cell.hpp"
#include "lbm/collision/collision_operator.hpp"
#include "lbm/d3q19.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace lbdem::lbm {

struct RegularizedLes {
  static constexpr std::string_view name = "regularized_les";
  // 0.1 (Deardorff 1970, J. Fluid Mech. 41, 453; Moin & Kim 1982, J. Fluid Mech. 118, 341): Lilly's
  // 0.17 holds for isotropic turbulence and is too dissipative in shear and near walls, where this
  // operator has no van Driest damping; the jet mill is jets, swirl and walls.
  static constexpr double kSmagorinskyDefault = 0.1;
  double tau0;         // molecular relaxation time [-]: nu0 = c_s^2 (tau0 - 1/2)
  double smagorinsky;  // C_s [-]; 0: plain regularized BGK

  static RegularizedLes from_tau(double tau, double c_s = kSmagorinskyDefault) {
    if (!(tau > 0.5))
      throw std::invalid_argument("regularized LES needs tau > 1/2, got " + std::to_string(tau));
    if (!(c_s >= 0))
      throw std::invalid_argument("Smagorinsky constant must be >= 0, got " + std::to_string(c_s));
    return {tau, c_s};
  }
  /// Molecular viscosity; the eddy part is per cell (eddy_viscosity()).
  double viscosity() const { return viscosity_from_tau(tau0); }

  /// Non-equilibrium stress Pi of a cell (pre-collision f, m with Guo-shifted u). Shifted
  /// populations (float, cell.hpp) give sum_q c c (f_q - w_q) = sum_q c c f_q - c_s^2 I, so the
  /// diagonal subtracts drho c_s^2 instead of rho c_s^2.
  template <class R>
  struct StressT {
    R xx, yy, zz, xy, xz, yz;
  };
  using Stress = StressT<double>;
  template <class R>
  [[gnu::always_inline]] static StressT<R> non_equilibrium_stress(const R (&f)[kQ],
                                                                  const CellMomentsT<R>& m) {
    StressT<R> s{-0.0, -0.0, -0.0, -0.0, -0.0, -0.0};
    static_for<kQ>([&](auto qc) LBDEM_INLINE {
      constexpr int q = decltype(qc)::value;
      constexpr int cx = kCx[q], cy = kCy[q], cz = kCz[q];
      if constexpr (cx != 0) s.xx += f[q];
      if constexpr (cy != 0) s.yy += f[q];
      if constexpr (cz != 0) s.zz += f[q];
      if constexpr (cx * cy == 1) s.xy += f[q];
      if constexpr (cx * cy == -1) s.xy -= f[q];
      if constexpr (cx * cz == 1) s.xz += f[q];
      if constexpr (cx * cz == -1) s.xz -= f[q];
      if constexpr (cy * cz == 1) s.yz += f[q];
      if constexpr (cy * cz == -1) s.yz -= f[q];
    });
    // Pi^eq = rho c_s^2 I + rho u u / eps.
    const R ru = m.rho * m.inv_eps, p = (kShifted<R> ? m.drho : m.rho) * R(kCs2);
    s.xx -= p + ru * m.ux * m.ux;
    s.yy -= p + ru * m.uy * m.uy;
    s.zz -= p + ru * m.uz * m.uz;
    s.xy -= ru * m.ux * m.uy;
    s.xz -= ru * m.ux * m.uz;
    s.yz -= ru * m.uy * m.uz;
    return s;
  }

  /// X = 18 sqrt(2) C_s^2 |Pi^c| / rho of the cell (header comment), with the Guo correction of Pi
  /// if forced.
  template <bool kForced, class R>
  [[gnu::always_inline]] R eddy_term(const StressT<R>& s, const CellMomentsT<R>& m,
                                     const CellForceT<R>& force) const {
    R xx = s.xx, yy = s.yy, zz = s.zz, xy = s.xy, xz = s.xz, yz = s.yz;
    if constexpr (kForced) {
      const R e = m.inv_eps, h = R(0.5) * m.inv_eps;
      xx += e * m.ux * force.fx;
      yy += e * m.uy * force.fy;
      zz += e * m.uz * force.fz;
      xy += h * (m.ux * force.fy + m.uy * force.fx);
      xz += h * (m.ux * force.fz + m.uz * force.fx);
      yz += h * (m.uy * force.fz + m.uz * force.fy);
    }
    const R norm = std::sqrt(xx * xx + yy * yy + zz * zz + R(2) * (xy * xy + xz * xz + yz * yz));
    return R(18.0 * std::sqrt(2.0) * smagorinsky * smagorinsky) * norm * m.inv_rho;
  }

  /// tau of the cell from Pi (Hou et al. 1996; header comment), with the Guo correction if forced.
  /// The root (tau0 + sqrt(tau0^2 + X)) / 2: a sum of two positive numbers, so without
  /// cancellation, and exactly tau0 at X = 0 (the correctly rounded square root of the rounded
  /// tau0^2 is tau0 in IEEE binary arithmetic). One division per cell fewer than the form
  /// tau0 + X / (2 (tau0 + sqrt(...))), which differs from it by round-off.
  template <bool kForced, class R>
  [[gnu::always_inline]] R local_tau(const StressT<R>& s, const CellMomentsT<R>& m,
                                     const CellForceT<R>& force) const {
    const R t0 = R(tau0), x = eddy_term<kForced>(s, m, force);
    return R(0.5) * (t0 + std::sqrt(t0 * t0 + x));
  }

  /// Effective tau = tau0 + nu_t / c_s^2 of a cell from its pre-collision populations; m must be
  /// cell_moments<forced>(f, force) with the same force (tests, banners).
  double effective_tau(const double (&f)[kQ], const CellMoments& m,
                       const CellForce& force = {}) const {
    return local_tau<true>(non_equilibrium_stress(f, m), m, force);
  }
  /// nu_t = (C_s Delta)^2 |S| [lattice units].
  double eddy_viscosity(const double (&f)[kQ], const CellMoments& m,
                        const CellForce& force = {}) const {
    return kCs2 * (effective_tau(f, m, force) - tau0);
  }

  // always_inline: GCC 12 otherwise leaves relax() a call inside the `omp simd` cell loop
  // (stream_collide.hpp), which then runs scalar: 17 against 21 MLUPS on a 64^3 box, and 38 once
  // -fno-math-errno lets std::sqrt vectorise too. R: double on f_q, float on f_q - w_q (cell.hpp).
  template <bool kForced, class R>
  [[gnu::always_inline]] void relax(R (&f)[kQ], const CellMomentsT<R>& m,
                                    const CellForceT<R>& force) const {
    const StressT<R> s = non_equilibrium_stress(f, m);
    // (1 - omega) w_q Q_q:Pi / (2 c_s^4) = w_q [a_q - b] with a_q = 4.5 (1 - omega) c c : Pi and
    // b = 1.5 (1 - omega) tr Pi.
    R pxx, pyy, pzz, pxy, pxz, pyz, source;
    // v -> (1 - omega) v. In float, tau0 near 1/2 (the jet mill's tau0 - 1/2 = 3.75e-5) would
    // quantise: omega = 1/tau near 2 and 1 - omega near -1 hold the viscosity in their last bits
    // (float's 6e-8 of 1 against 2 (tau - 1/2) = 7.5e-5: 8e-4 of nu0). So single precision carries
    // tau - 1/2 = (tau0 - 1/2) + X / (2 (sqrt(tau0^2 + X) + tau0)) from the exact tau0 - 1/2, and
    // kappa = 2 - omega = 2 (tau - 1/2) / tau, with (1 - omega) v = kappa v - v and
    // 1 - omega/2 = kappa/2: the viscosity to float's relative 6e-8 at any tau0.
    [[maybe_unused]] R omega, kappa;
    if constexpr (kShifted<R>) {
      const R t0 = R(tau0), x = eddy_term<kForced>(s, m, force);
      const R d = R(tau0 - 0.5) + x / (R(2) * (std::sqrt(t0 * t0 + x) + t0));
      kappa = R(2) * d / (R(0.5) + d);
      const R k45 = R(4.5) * kappa, k9 = R(9) * kappa;
      pxx = k45 * s.xx - R(4.5) * s.xx;
      pyy = k45 * s.yy - R(4.5) * s.yy;
      pzz = k45 * s.zz - R(4.5) * s.zz;
      pxy = k9 * s.xy - R(9) * s.xy;
      pxz = k9 * s.xz - R(9) * s.xz;
      pyz = k9 * s.yz - R(9) * s.yz;
      source = R(0.5) * kappa;
    } else {
      omega = R(1) / local_tau<kForced>(s, m, force);
      const R r = R(4.5) * (R(1) - omega);
      pxx = r * s.xx;
      pyy = r * s.yy;
      pzz = r * s.zz;
      pxy = R(2) * r * s.xy;
      pxz = R(2) * r * s.xz;
      pyz = R(2) * r * s.yz;
      source = R(1) - R(0.5) * omega;
    }
    const R b = (pxx + pyy + pzz) * R(kCs2);
    const R usq = R(1.5) * m.inv_eps * (m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);
    const R quad = R(4.5) * m.inv_eps;
    [[maybe_unused]] const R uf =
        R(3) * m.inv_eps * (m.ux * force.fx + m.uy * force.fy + m.uz * force.fz);
    // With a force, f^neq also has a first moment, j - rho u (-F/2 for Guo's u): kept, relaxed
    // with (1 - omega) as in BGK, so that momentum gains (1 - omega/2) F + omega (rho u - j) = F
    // whatever the definition of u. Unforced it is round-off and left out.
    [[maybe_unused]] R gx = 0, gy = 0, gz = 0;  // 3 (1 - omega) (j - rho u) + 3 source F
    if constexpr (kForced) {
      R jx = -0.0, jy = -0.0, jz = -0.0;
      static_for<kQ>([&](auto qc) LBDEM_INLINE {
        constexpr int q = decltype(qc)::value;
        if constexpr (kCx[q] != 0) jx += R(kCx[q]) * f[q];
        if constexpr (kCy[q] != 0) jy += R(kCy[q]) * f[q];
        if constexpr (kCz[q] != 0) jz += R(kCz[q]) * f[q];
      });
      const R c = R(3) * source;
      if constexpr (kShifted<R>) {
        const R k3 = R(3) * kappa;
        const R dx = jx - m.rho * m.ux, dy = jy - m.rho * m.uy, dz = jz - m.rho * m.uz;
        gx = (k3 * dx - R(3) * dx) + c * force.fx;
        gy = (k3 * dy - R(3) * dy) + c * force.fy;
        gz = (k3 * dz - R(3) * dz) + c * force.fz;
      } else {
        const R a = R(3) * (R(1) - omega);
        gx = a * (jx - m.rho * m.ux) + c * force.fx;
        gy = a * (jy - m.rho * m.uy) + c * force.fy;
        gz = a * (jz - m.rho * m.uz) + c * force.fz;
      }
    }
    static_for<kQ>([&](auto qc) LBDEM_INLINE {
      constexpr int q = decltype(qc)::value;
      constexpr int cx = kCx[q], cy = kCy[q], cz = kCz[q];
      const R cu = dot_c<q>(m.ux, m.uy, m.uz);
      R neq = -b;
      if constexpr (cx != 0) neq += pxx;
      if constexpr (cy != 0) neq += pyy;
      if constexpr (cz != 0) neq += pzz;
      if constexpr (cx * cy == 1) neq += pxy;
      if constexpr (cx * cy == -1) neq -= pxy;
      if constexpr (cx * cz == 1) neq += pxz;
      if constexpr (cx * cz == -1) neq -= pxz;
      if constexpr (cy * cz == 1) neq += pyz;
      if constexpr (cy * cz == -1) neq -= pyz;
      R post;
      if constexpr (kShifted<R>)
        post = R(kW[q]) * (m.drho + m.rho * (R(3) * cu + quad * cu * cu - usq) + neq);
      else
        post = kW[q] * (m.rho * (1.0 + 3.0 * cu + quad * cu * cu - usq) + neq);
      if constexpr (kForced) {
        const R cf = dot_c<q>(force.fx, force.fy, force.fz);
        post += R(kW[q]) * (dot_c<q>(gx, gy, gz) + source * (R(9) * m.inv_eps * cu * cf - uf));
      }
      f[q] = post;
    });
  }
};

}  // namespace lbdem::lbm

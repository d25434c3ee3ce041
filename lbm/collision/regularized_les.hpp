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

  /// Non-equilibrium stress Pi of a cell (pre-collision f, m with Guo-shifted u).
  struct Stress {
    double xx, yy, zz, xy, xz, yz;
  };
  [[gnu::always_inline]] static Stress non_equilibrium_stress(const double (&f)[kQ],
                                                              const CellMoments& m) {
    Stress s{-0.0, -0.0, -0.0, -0.0, -0.0, -0.0};
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
    const double ru = m.rho * m.inv_eps, p = m.rho * kCs2;
    s.xx -= p + ru * m.ux * m.ux;
    s.yy -= p + ru * m.uy * m.uy;
    s.zz -= p + ru * m.uz * m.uz;
    s.xy -= ru * m.ux * m.uy;
    s.xz -= ru * m.ux * m.uz;
    s.yz -= ru * m.uy * m.uz;
    return s;
  }

  /// tau of the cell from Pi (Hou et al. 1996; header comment), with the Guo correction if forced.
  template <bool kForced>
  [[gnu::always_inline]] double local_tau(const Stress& s, const CellMoments& m,
                                          const CellForce& force) const {
    double xx = s.xx, yy = s.yy, zz = s.zz, xy = s.xy, xz = s.xz, yz = s.yz;
    if constexpr (kForced) {
      const double e = m.inv_eps, h = 0.5 * m.inv_eps;
      xx += e * m.ux * force.fx;
      yy += e * m.uy * force.fy;
      zz += e * m.uz * force.fz;
      xy += h * (m.ux * force.fy + m.uy * force.fx);
      xz += h * (m.ux * force.fz + m.uz * force.fx);
      yz += h * (m.uy * force.fz + m.uz * force.fy);
    }
    const double norm =
        std::sqrt(xx * xx + yy * yy + zz * zz + 2.0 * (xy * xy + xz * xz + yz * yz));
    // The root (tau0 + sqrt(tau0^2 + X)) / 2, X = 18 sqrt(2) C_s^2 |Pi^c| / rho: a sum of two
    // positive numbers, so without cancellation, and exactly tau0 at X = 0 (the correctly rounded
    // square root of the rounded tau0^2 is tau0 in IEEE binary arithmetic). One division per cell
    // fewer than the form tau0 + X / (2 (tau0 + sqrt(...))), which differs from it by round-off.
    const double x = 18.0 * std::sqrt(2.0) * smagorinsky * smagorinsky * norm * m.inv_rho;
    return 0.5 * (tau0 + std::sqrt(tau0 * tau0 + x));
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
  // -fno-math-errno lets std::sqrt vectorise too.
  template <bool kForced>
  [[gnu::always_inline]] void relax(double (&f)[kQ], const CellMoments& m,
                                    const CellForce& force) const {
    const Stress s = non_equilibrium_stress(f, m);
    const double omega = 1.0 / local_tau<kForced>(s, m, force);
    // (1 - omega) w_q Q_q:Pi / (2 c_s^4) = w_q [a_q - b] with a_q = 4.5 (1 - omega) c c : Pi and
    // b = 1.5 (1 - omega) tr Pi.
    const double r = 4.5 * (1.0 - omega);
    const double pxx = r * s.xx, pyy = r * s.yy, pzz = r * s.zz;
    const double pxy = 2.0 * r * s.xy, pxz = 2.0 * r * s.xz, pyz = 2.0 * r * s.yz;
    const double b = (pxx + pyy + pzz) * kCs2;
    const double usq = 1.5 * m.inv_eps * (m.ux * m.ux + m.uy * m.uy + m.uz * m.uz);
    const double quad = 4.5 * m.inv_eps;
    [[maybe_unused]] const double source = 1.0 - 0.5 * omega;
    [[maybe_unused]] const double uf =
        3.0 * m.inv_eps * (m.ux * force.fx + m.uy * force.fy + m.uz * force.fz);
    // With a force, f^neq also has a first moment, j - rho u (-F/2 for Guo's u): kept, relaxed
    // with (1 - omega) as in BGK, so that momentum gains (1 - omega/2) F + omega (rho u - j) = F
    // whatever the definition of u. Unforced it is round-off and left out.
    [[maybe_unused]] double gx = 0, gy = 0, gz = 0;  // 3 (1 - omega) (j - rho u) + 3 source F
    if constexpr (kForced) {
      double jx = -0.0, jy = -0.0, jz = -0.0;
      static_for<kQ>([&](auto qc) LBDEM_INLINE {
        constexpr int q = decltype(qc)::value;
        if constexpr (kCx[q] != 0) jx += kCx[q] * f[q];
        if constexpr (kCy[q] != 0) jy += kCy[q] * f[q];
        if constexpr (kCz[q] != 0) jz += kCz[q] * f[q];
      });
      const double a = 3.0 * (1.0 - omega), c = 3.0 * source;
      gx = a * (jx - m.rho * m.ux) + c * force.fx;
      gy = a * (jy - m.rho * m.uy) + c * force.fy;
      gz = a * (jz - m.rho * m.uz) + c * force.fz;
    }
    static_for<kQ>([&](auto qc) LBDEM_INLINE {
      constexpr int q = decltype(qc)::value;
      constexpr int cx = kCx[q], cy = kCy[q], cz = kCz[q];
      const double cu = dot_c<q>(m.ux, m.uy, m.uz);
      double neq = -b;
      if constexpr (cx != 0) neq += pxx;
      if constexpr (cy != 0) neq += pyy;
      if constexpr (cz != 0) neq += pzz;
      if constexpr (cx * cy == 1) neq += pxy;
      if constexpr (cx * cy == -1) neq -= pxy;
      if constexpr (cx * cz == 1) neq += pxz;
      if constexpr (cx * cz == -1) neq -= pxz;
      if constexpr (cy * cz == 1) neq += pyz;
      if constexpr (cy * cz == -1) neq -= pyz;
      double post = kW[q] * (m.rho * (1.0 + 3.0 * cu + quad * cu * cu - usq) + neq);
      if constexpr (kForced) {
        const double cf = dot_c<q>(force.fx, force.fy, force.fz);
        post += kW[q] * (dot_c<q>(gx, gy, gz) + source * (9.0 * m.inv_eps * cu * cf - uf));
      }
      f[q] = post;
    });
  }
};

}  // namespace lbdem::lbm

#pragma once
// Per-cell state shared by the kernel, the collision operators and the moment fields.
#include "lbm/d3q19.hpp"

#include <limits>
#include <type_traits>

namespace lbdem::lbm {

/// The arithmetic of a cell update runs in R. Float arithmetic always works on shifted populations
/// f_q - w_q (pdf_field.hpp, "DDF shifting"): f_q - w_q is of the order of w_q times the density
/// and velocity deviations, so float's 24 bits resolve the deviations instead of the constant w_q;
/// the density is then carried as drho = rho - 1 beside rho, and every equilibrium is formed
/// shifted, never as a value near w_q minus w_q. Double arithmetic works on f_q itself (the
/// reference mode, bitwise as before single precision existed).
template <class R>
inline constexpr bool kShifted = std::is_same_v<R, float>;

/// Density and the physical velocity of one cell [lattice units].
/// inv_eps = 1/eps of the porous (Guo & Zhao 2002) form: it multiplies the terms of second order
/// in u of the equilibrium and of the Guo source; 1 without porosity. inv_rho = 1/rho, kept from
/// cell_moments so that the porous drag and the LES eddy viscosity multiply instead of dividing.
/// Why: the jet mill's porous LES kernel spent 7 divisions and 4 square roots per cell; at the
/// divider's throughput (an AVX2 vdivpd of 4 doubles about 8 cycles, a vsqrtpd about 12) that is
/// an estimated quarter of its time. Down to 3 and 2 (with porous.hpp and regularized_les.hpp),
/// its stream-collide took 24.3 s instead of 31.0 s on 1.5 ms of cg8_p5bar (2 threads,
/// 2026-11-24).
/// drho = rho - 1, formed from the shifted populations (kShifted<R>); what shifted equilibria use.
template <class R>
struct CellMomentsT {
  R rho, ux, uy, uz;
  R inv_eps = 1;
  // Set by cell_moments; NaN otherwise, so that a hand-built CellMoments cannot pass silently.
  R inv_rho = std::numeric_limits<R>::quiet_NaN();
  R drho = std::numeric_limits<R>::quiet_NaN();
};
using CellMoments = CellMomentsT<double>;

/// Body force density acting on one cell [lattice units: mass / (cell dt^2)].
template <class R>
struct CellForceT {
  R fx = 0, fy = 0, fz = 0;
};
using CellForce = CellForceT<double>;

namespace detail {
// The hand-written sums below rely on this direction order (d3q19.hpp).
constexpr bool moment_sums_match_order() {
  constexpr int px[] = {1, 7, 9, 11, 13}, mx[] = {2, 8, 10, 12, 14};
  constexpr int py[] = {3, 7, 10, 15, 17}, my[] = {4, 8, 9, 16, 18};
  constexpr int pz[] = {5, 11, 14, 15, 18}, mz[] = {6, 12, 13, 16, 17};
  for (int k = 0; k < 5; ++k)
    if (kCx[px[k]] != 1 || kCx[mx[k]] != -1 || kCy[py[k]] != 1 || kCy[my[k]] != -1 ||
        kCz[pz[k]] != 1 || kCz[mz[k]] != -1)
      return false;
  return kCx[3] == 0 && kCx[4] == 0 && kCx[5] == 0 && kCx[6] == 0 && kCx[15] == 0 && kCx[16] == 0 &&
         kCx[17] == 0 && kCx[18] == 0;
}
static_assert(moment_sums_match_order());
}  // namespace detail

/// rho = sum_q f_q and u = (sum_q c_q f_q + F/2) / rho: the half-force shift makes Guo forcing
/// second-order accurate (Guo, Zheng & Shi 2002, Phys. Rev. E 65, 046308, eq. 19). The sums are
/// trees, not chains, so a vector lane is not one 19-add dependency chain; their order is fixed.
/// Shifted (float): the same sums of f_q - w_q give drho directly and the momentum unchanged
/// (sum_q w_q c_q = 0).
template <bool kForced, class R>
[[gnu::always_inline]] inline CellMomentsT<R> cell_moments(const R (&f)[kQ],
                                                           const CellForceT<R>& force) {
  const R xp = (f[1] + f[7]) + (f[9] + f[11]) + f[13];
  const R xm = (f[2] + f[8]) + (f[10] + f[12]) + f[14];
  const R rest = ((f[0] + f[3]) + (f[4] + f[5])) + ((f[6] + f[15]) + (f[16] + f[17])) + f[18];
  const R sum = (xp + xm) + rest;
  R jx = xp - xm;
  R jy = ((f[3] - f[4]) + (f[7] - f[8])) + ((f[10] - f[9]) + (f[15] - f[16])) + (f[17] - f[18]);
  R jz = ((f[5] - f[6]) + (f[11] - f[12])) + ((f[14] - f[13]) + (f[15] - f[16])) + (f[18] - f[17]);
  if constexpr (kForced) {
    jx += R(0.5) * force.fx;
    jy += R(0.5) * force.fy;
    jz += R(0.5) * force.fz;
  }
  const R rho = kShifted<R> ? sum + R(1) : sum;
  const R drho = kShifted<R> ? sum : sum - R(1);  // unused (and dropped) in double
  const R inv = R(1) / rho;
  return {rho, jx * inv, jy * inv, jz * inv, R(1), inv, drho};
}

/// The rest population that gives a shifted cell the mass drho: drho - sum_{q >= 1} f_q (a tree
/// sum, order fixed). Every collision operator and its forcing conserve the cell's mass, but formed
/// with the weights rounded to float they do not quite: sum_q float(w_q) = 1 + 1.49e-8 and
/// sum_q float(w_q) c_qx^2 = (1 + 7.45e-9) / 3, so each collision changed the mass by about
/// 7e-9 (2 drho - 1.5 u^2 / eps) of the cell's, with the same sign every step (a drift of 6e-7 in
/// the density of a closed Couette channel over 56,700 steps). Setting the rest population last
/// leaves only the rounding of this sum, which has no sign of its own.
template <class R>
[[gnu::always_inline]] inline R rest_from_mass(const R (&f)[kQ], R drho) {
  const R a = ((f[1] + f[2]) + (f[3] + f[4])) + ((f[5] + f[6]) + (f[7] + f[8])) + f[9];
  const R b = ((f[10] + f[11]) + (f[12] + f[13])) + ((f[14] + f[15]) + (f[16] + f[17])) + f[18];
  return drho - (a + b);
}

}  // namespace lbdem::lbm

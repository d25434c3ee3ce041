#pragma once
// A wall function for under-resolved LES: the wall stress comes from a law of the wall instead of
// the no-slip gradient across the first cell, and is imposed exactly through the slip velocity of
// the bounce-back links (the inverse momentum exchange method of Asmuth, Janssen,
// Olivares-Espinosa & Ivanell 2021, Phys. Fluids 33, 105111).
//
// Why: with dx far above the viscous length, half-way bounce-back sets the wall stress to
// rho (nu + nu_t) u_1 / (dx / 2), and the Smagorinsky nu_t of the first cell, (C_s dx)^2 |S|, is
// largest exactly there (no van Driest damping). In the jet mill (dx = 0.5 mm, u_1 ~ 30 m/s) that
// is about 90 Pa where a turbulent boundary layer carries about 6 Pa, so the walls brake the
// vortex about 15 times too hard.
//
// Law: Werner & Wengle 1991 (8th Symp. Turbulent Shear Flows, Munich), u+ = y+ for
// y+ <= A^(1/(1-B)) = 11.81 and u+ = A y+^B above, A = 8.3, B = 1/7, integrated over the first
// cell (height dz, wall at its face) so that the cell's mean speed u gives tau_w in closed form:
//   tau_w / rho = 2 nu u / dz,  if u <= nu A^(2/(1-B)) / (2 dz);
//   tau_w / rho = [ (1-B)/2 A^((1+B)/(1-B)) (nu/dz)^(1+B) + (1+B)/A (nu/dz)^B u ]^(2/(1+B)),
//   otherwise.
// The first branch is the stress of half-way bounce-back for a linear profile across the first
// cell, so inside the viscous sublayer the function differs from no slip only by the profile's
// curvature (in Poiseuille flow a uniform shift of F / (8 nu); tests/lbm/test_wall_function.cpp).
// Staircase limits: at a concave edge within one body the cell's area 6 |sum w_q c_q| is about
// 1.2 where two faces give 2, and the normal is the diagonal. The cell's velocity is the one its
// collision relaxed towards (forcing/moment_store.hpp): half-force shift and, in porous cells, the
// implicit drag included, divided by eps (the interstitial gas velocity the law is written for).
//
// Imposition, per fluid cell next to the wall (its links are contiguous in the body's list):
// with post-collision populations f_q*, the links give the wall F = sum_q c_q (2 f_q* + corr_q)
// with corr_q = -6 w_q rho_w c_q . u_s (Ladd's term for a wall point moving at u_s), i.e.
// F = 2 P - M u_s, P = sum_q c_q f_q*, M = 6 rho_w sum_q w_q c_q c_q^T. The slip velocity u_s,
// tangential to the cell's wall normal n, is the solution of the tangential part of
//   F_t = tau_w A t,   t = u_t / |u_t|,
// A the cell's wall area. n = -sum_q w_q c_q / |.|, so sum_q corr_q = 6 rho_w |.| n . u_s = 0: the
// links add no mass, on flat and staircase walls alike. For a flat face n is the face normal,
// A = 1 and M_t = rho_w / 3 I; on a staircase A = 6 |sum_q w_q c_q| (a flat face's 1/6 per unit
// area) and M_t is solved by a pseudo-inverse: a link along n carries no tangential momentum.
// The normal momentum exchange of a flat wall is that of a wall at rest. The slip is bounded to
// lie between no slip and the cell's tangential velocity (along the flow), which the equilibrium
// layer never reaches; without the bound the explicit slip diverged the jet mill's floor at 14 ms.
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/bounce_back.hpp"
#include "lbm/forcing/moment_store.hpp"
#include "lbm/pdf_field.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace lbdem::lbm {

/// Werner & Wengle's power law, cell-averaged (header comment) [lattice units or any consistent].
struct WernerWengle {
  static constexpr double kA = 8.3;
  static constexpr double kB = 1.0 / 7.0;
  double nu;  // molecular kinematic viscosity
  /// tau_w / rho for the mean speed u >= 0 of a first cell of height dz whose face is the wall.
  double kinematic_stress(double u, double dz = 1.0) const;
};

/// The same law for one cell height, with its constants evaluated once: two square roots per call
/// instead of five pows (the wall function runs on every wall cell every step).
struct WernerWengleCell {
  double switch_speed;  // top of the linear branch
  double linear;        // 2 nu / dz
  double c0, c1;  // the power branch's (1-B)/2 A^((1+B)/(1-B)) (nu/dz)^(1+B) and (1+B)/A (nu/dz)^B
  WernerWengleCell(const WernerWengle& law, double dz = 1.0);
  double kinematic_stress(double u) const {
    // 2 / (1 + B) = 7/4: x^(7/4) = x sqrt(x sqrt(x)), two roots in place of a pow (the pow
    // alone took 3.5 % of the default jet mill run).
    static_assert(WernerWengle::kB == 1.0 / 7.0);
    if (u <= switch_speed) return linear * u;
    const double x = c0 + c1 * u;
    return x * std::sqrt(x * std::sqrt(x));
  }
};

/// The fluid cells of one body's links, with what the wall function needs of each, SoA.
struct WallFunctionCells {
  std::vector<Index> cell;           // storage index of the fluid cell
  std::vector<std::uint32_t> first;  // its links: first[i] .. first[i + 1] - 1 (size + 1 entries)
  std::vector<Vec3> normal;          // unit, into the fluid
  std::vector<Vec3> e1, e2;          // tangent basis
  std::vector<double> area;          // wall area [cells^2]
  std::vector<std::array<double, 3>> m_pinv;  // pseudo-inverse of M_t / rho_w: (11, 12, 22)
  // The cell's centre [lattice coordinates]. Its links act at x + c_q / 2, and c_q x c_q = 0, so
  // their torque is (x - origin) x F_cell: one cross product per cell instead of one per link.
  std::vector<Vec3> centre;
  // Work units in storage order: cells unit_first[u] .. unit_first[u + 1] - 1 (units + 1 entries),
  // either one cell or, where unit_flat[u], a run of flat-face cells: storage neighbours with the
  // five links of one axis-aligned face, in the same order and to the same offsets. There n is
  // the face's axis, A = 1 and M_t / rho_w = I / 3 exactly, and each link's slots are consecutive
  // along the run, so the kernel is one branch-free loop (80 % of the jet mill's wall cells are
  // floor and top-plate cells in runs of about 22).
  std::vector<std::uint32_t> unit_first;
  std::vector<std::uint8_t> unit_flat;
  // Blocks of units of about kWallCellBlock cells each (block_first), fixed at
  // set-up (blocks + 1 entries): the load is summed block by block, bitwise the same at any
  // thread count.
  std::vector<std::uint32_t> block_first;
  std::size_t size() const { return cell.size(); }
};

/// Groups a body's links (build_links: contiguous per fluid cell) by cell. `flat_runs` false
/// keeps every cell on the general kernel (the reference the flat-face kernel is tested against).
WallFunctionCells build_wall_function_cells(const BounceBackLinks& links, bool flat_runs = true);

/// Applies the links of a body at rest with the wall function, for the state `now` the step has
/// just produced (bounce_back.hpp); returns the wall's force, torque about `origin` and the mass
/// given to the fluid (round-off), bitwise the same for any thread count. Writes each link's
/// correction into `links` (the last step's slip terms, for inspection).
template <class T>
WallLoad apply_wall_function(PdfField<T>& pdf, AaState now, BounceBackLinks& links,
                             const WallFunctionCells& cells, const WernerWengle& law,
                             const MomentFields<T>& moments, double rho_w,
                             const Vec3& origin = Vec3::Zero());

}  // namespace lbdem::lbm

#pragma once
// Pressure (density) outlet by anti-bounce-back on the links of a body, listed like a wall's
// (bounce_back.hpp; Ginzburg, Verhaeghe & d'Humieres 2008, Commun. Comput. Phys. 3, 427; Kruger et
// al. 2017, The Lattice Boltzmann Method, sec. 5.3.4):
//   f_qbar(x, t+1) = -f_q*(x, t) + 2 w_q rho_out [1 + (c_q.u_w)^2/(2 c_s^4) - u_w^2/(2 c_s^2)]
// for every link from fluid cell x along c_q into the outlet. f_q + f_qbar of the equilibrium is
// the bracket, so the rule fixes the even (density) part at the half-way point to rho_out, i.e. the
// pressure rho_out c_s^2, and lets the odd (momentum) part through: the gas leaves or enters at
// whatever velocity the interior sets.
//
// u_w is the velocity at the half-way point, extrapolated linearly from the fluid cell and the next
// one inward at time t:  u_w = u(x) + [u(x) - u(x - c_q)] / 2  (Kruger et al. 2017, sec. 5.3.4).
// Taking u_w = u(x) instead puts an O(|du/dx|) error into the O(u^2) terms, a first-order pressure
// error wherever the flow still develops at the outlet (a jet, a wake); the extrapolation keeps the
// second order. Where x - c_q is not fluid (a wall edge, a one-cell-deep domain) it falls back to
// u(x). The extrapolation can be switched off per outlet (u_w = u(x)): it weighs u(x) by 3/2 and
// its neighbour by -1/2, which feeds a cell-to-cell oscillation back into the bracket's (c_q.u_w)^2
// term. Where a strong swirl crosses the outlet (the jet mill's vortex finder, tangential speed
// far above the through-flow) that term is large and the feedback diverged the gas within 16 ms
// (lattice velocity 0.07 and 0.1); with u_w = u(x) the same run stayed stable (measured). The
// velocities are sampled before the step's kernel from the populations in the current AA state
// (moments.hpp, Guo-corrected), when all of them are still in place.
//
// Backflow can be shut per outlet: a link that would add mass (f_qbar > f_q*), or whose cell moves
// into the domain (u . n < 0, n the cell's outward normal, the weighted mean of its outlet links'
// directions), bounces back as a wall at rest for that step, so gas only leaves. Why: a swirl
// crossing the outlet has a low-pressure core; at a fixed outlet pressure gas is drawn in along the
// core, which strengthens the core and draws more. In the jet mill's vortex finder that inflow grew
// from -21 m/s (33.4 ms) to -142 m/s (34.3 ms) and the gas diverged at 34.6 ms; with backflow shut
// (or with a local, mean-fixed outlet pressure) the same state ran stably to 60 ms (measured).
// Fluent's "prevent reverse flow" option for pressure outlets is the same idea.
//
// The equilibrium bracket is the free-gas one (eps = 1): outlets belong in particle-free gas, where
// the porous form's 1/eps terms (forcing/porous.hpp) are 1.
//
// Per step and link the fluid gains the mass f_qbar(x, t+1) - f_q*(x, t) (negative: outflow) and
// the body the momentum c_q [f_q*(x, t) + f_qbar(x, t+1)] (the pressure force on the outlet).
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/bounce_back.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/moments.hpp"
#include "lbm/pdf_field.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lbdem::lbm {

/// The outlet's data beside its BounceBackLinks (which give fluid cell, solid cell, q, point).
struct PressureOutlet {
  double density = 1.0;                    // rho_out at the half-way points [lattice units]
  bool extrapolate = true;                 // u_w extrapolated to the half-way point, else u(x)
  bool backflow = true;                    // false: links of a cell with inflow bounce back
  std::vector<Vec3> normal;                // per cell: outward unit normal of its outlet links
  std::vector<std::array<int, 3>> cells;   // fluid cells whose velocity the links read
  std::vector<Vec3> velocity;              // u(t) of each cell, sampled before the step
  std::vector<std::uint32_t> near_cell;    // per link: position in cells of x
  std::vector<std::uint32_t> inward_cell;  // per link: of x - c_q (== near_cell: not fluid)
};

/// Lists the cells the outlet's links read, each once, in order of first use.
PressureOutlet build_outlet(const BounceBackLinks& links, const FlagField& flags, double density,
                            bool extrapolate = true, bool backflow = true);

/// Samples u(x, t) of every listed cell from state s (before the step), with the step's forcing
/// and the mass sources the step adds as it collides (pending_mass, per storage cell; null: none).
/// Each cell writes its own entry: the same values at any thread count. A small outlet stays on one
/// thread, where a parallel region would cost more than the 19 loads per cell.
template <class T, class Forcing>
void sample_outlet_velocity(const PdfField<T>& pdf, AaState s, const Forcing& forcing,
                            PressureOutlet& o, const double* pending_mass = nullptr) {
  const auto n = static_cast<std::ptrdiff_t>(o.cells.size());
#pragma omp parallel for schedule(static) if (n > 1024)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto [x, y, z] = o.cells[std::size_t(i)];
    const CellMoments m = cell_moments_at(pdf, s, forcing, x, y, z, pending_mass);
    o.velocity[std::size_t(i)] = Vec3(m.ux, m.uy, m.uz);
  }
}

/// Applies the outlet's links for the state the step has just produced (the same slots as
/// apply_bounce_back); returns the force and torque on the outlet and the mass it gave the fluid
/// in this step (negative: outflow) [lattice units], as fixed-block sums.
template <class T>
WallLoad apply_anti_bounce_back(PdfField<T>& pdf, AaState now, const BounceBackLinks& links,
                                const PressureOutlet& outlet, const Vec3& origin = Vec3::Zero());

}  // namespace lbdem::lbm

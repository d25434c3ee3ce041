#pragma once
// Free-slip and partial-slip walls on the flat faces of the box: the combination of half-way
// bounce-back and specular reflection (Succi 2002, Phys. Rev. Lett. 89, 064502; Sbragaglia & Succi
// 2005, Phys. Fluids 17, 093602; with TRT/MRT: Verhaeghe, Luo & Blanpain 2009, J. Comput. Phys.
// 228, 147). A face with slip fraction s in [0, 1] returns the population f_q*(x, t) that leaves
// fluid cell x along c_q into the wall (c_q . n < 0, n the inward unit normal) as
//   bounce-back, weight 1 - s:  f_qbar(x, t+1)            = f_q*(x, t)
//   specular,    weight s:      f_q'(x + c_t, t+1)        = f_q*(x, t),
// with c_q' = c_q - 2 (c_q . n) n and c_t = c_q - (c_q . n) n: the population travels half a link
// to the wall, has its normal velocity reversed, and lands one tangential step further on. Seen
// from the receiving end, the unknown f_qbar(y, t+1) of the link (y, q) is
//   f_qbar(y, t+1) = (1 - s) f_q*(y, t) + s f_r*(y + c_qt, t),   c_r = c_qn - c_qt,
// so each link writes one slot (its own, as for bounce-back) and reads two: its own outgoing
// population and its partner's, (y + c_qt, r). Partners come in pairs (the partner of (y + c_qt,
// r) is (y, q)), so each outgoing population is handed out with total weight 1: the mass is
// conserved link pair by link pair. A link whose partner is not a link of the same face (the
// tangential neighbour y + c_qt is not a fluid cell: an edge where two faces meet, an inlet or
// outlet ghost, a solid cell; or the partner's target is not this face's ghost) stays plain
// bounce-back, and so does its would-be partner; y + c_qt wraps on periodic axes. A normal link
// (c_qt = 0) is its own partner and bounces back at any s.
//
// Under the AA pattern (aa_pattern.hpp, bounce_back.hpp) f_q*(y, t) sits in slot qbar of y after
// an even step and in slot q of the ghost y + c_q after an odd one; the unknown goes to slot q of
// y + c_q, respectively slot qbar of y. The slots a pass reads ("from") and those it writes ("to")
// are disjoint (fluid slots and ghost slots, swapped between the states), and no live population
// sits in a "from" slot, so the pass runs on all links at once in any order.
//
// The value is computed as f = a + s (b - a) (a: own outgoing, b: the partner's), which is exactly
// a for s small enough and exactly b for s = 1 (taken as b, no arithmetic). Momentum exchange, per
// link attributed to the population that leaves through it: the normal momentum of f_q*(y, t) is
// always reversed, 2 f_q* c_qn to the wall; its tangential momentum is reversed by the
// bounce-back share only, 2 (1 - s) f_q* c_qt. Summed over a link pair this is the momentum the
// fluid loses; for s = 1 the tangential force is exactly 0, for s = 0 it is the bounce-back force.
// The mass given to the fluid is 0 (the wall is at rest: moving slip walls are refused).
//
// Steady plane Poiseuille flow between two such walls, driven by a force density G along them,
// with BGK or TRT and Guo forcing (D3Q19; the shear is carried by the four diagonals in the plane
// of the flow and the wall normal, with the same weights 1/36 as in D2Q9) solves exactly to first
// order in u (tests/lbm/test_slip_walls.cpp gives the derivation):
//   u(zeta) = G zeta (H - zeta) / (2 nu) + u_s,
//   u_s = (3/2) G H s / (1 - s) + (16 Lambda - 3) G / (24 nu),
// with zeta the distance from the half-way wall, H the width, Lambda = (tau+ - 1/2)(tau- - 1/2).
// The first term is the slip of the blend (a slip length 3 nu s / (1 - s) in lattice units), the
// second bounce-back's own Lambda-dependent slip, zero for TRT at Lambda = 3/16.
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/bounce_back.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/pdf_field.hpp"

#include <cstdint>
#include <vector>

namespace lbdem::lbm {

/// The slip links of one face, SoA: link k is (fluid[k], dir[k]) into the ghost solid[k]; its
/// partner is (partner_fluid[k], partner_dir[k]) into partner_solid[k].
struct SlipLinks {
  double slip = 1.0;  // s in (0, 1]
  int axis = 2;       // of the wall normal
  std::vector<Index> fluid, solid, partner_fluid, partner_solid;
  std::vector<std::uint8_t> dir, partner_dir;
  std::vector<Vec3> point;  // half-way wall point x + c_q / 2 [lattice coordinates]
  std::size_t size() const { return fluid.size(); }
  bool empty() const { return fluid.empty(); }
};

/// Moves the links of a face (body `body`, inward normal sign * e_axis) that have a specular
/// partner out of `links` into the returned list; the others stay in `links` as bounce-back.
/// Throws std::invalid_argument unless 0 < slip <= 1.
SlipLinks split_slip_links(BounceBackLinks& links, const FlagField& flags, CellFlag body, int axis,
                           int sign, double slip);

/// Applies the links for the state the step has just produced; returns the momentum given to the
/// wall, its torque about `origin` and the mass given to the fluid (0) [lattice units].
template <class T>
WallLoad apply_slip_links(PdfField<T>& pdf, AaState now, const SlipLinks& links,
                          const Vec3& origin = Vec3::Zero());

}  // namespace lbdem::lbm

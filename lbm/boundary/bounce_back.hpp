#pragma once
// Half-way bounce-back on a list of links (waLBerla's per-link treatDirection), with Ladd's
// moving-wall term and the momentum-exchange force:
//   f_qbar(x, t+1) = f_q*(x, t) - 2 w_q rho_w (c_q . u_w) / c_s^2   (Ladd 1994, JFM 271, eq. 3.2)
//   F_wall += c_q [ f_q*(x, t) + f_qbar(x, t+1) ] = c_q [ 2 f_q*(x, t) + corr_q ]
// for every link from fluid cell x along c_q into a solid cell (Ladd 1994 eq. 3.4; momentum given
// to the body per step, i.e. the force in lattice units). The wall sits half-way along the link.
// The mass the link gives the fluid per step is f_qbar(x, t+1) - f_q*(x, t) = corr_q: zero for a
// wall at rest, cancelling in pairs for a tangentially moving one, and the inflow of a velocity
// inlet (a "wall" moving into the fluid; Kruger et al. 2017, The Lattice Boltzmann Method,
// sec. 5.3). For a plug u_w = U e_x on an x face, the five links of one cell give
// 2 (1/6) rho_w U / c_s^2 = rho_w U, the exact inflow per face cell.
//
// Links are listed once at set-up from the flag field; the step applies them after the kernel.
// With the AA pattern (aa_pattern.hpp) the incoming value is placed where the next read expects it:
//   state swapped (after an even step): f_q* sits in slot qbar of x, and the next step reads
//     f_qbar(x) from slot q of x + c_q, the solid cell;
//   state natural (after an odd step): f_q* was streamed into slot q of the solid x + c_q, and
//     f_qbar(x) is read from slot qbar of x.
// Every link writes one slot of its own, so the pass runs in parallel; the force is a fixed-block
// sum, bitwise the same at any thread count.
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/pdf_field.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace lbdem::lbm {

/// Velocity of a wall at a point [lattice units]; x in lattice coordinates (cell centres at
/// integers, so a half-way wall point is x_fluid + c_q / 2).
using WallVelocity = std::function<Vec3(const Vec3& x)>;

/// The links of one body, SoA.
struct BounceBackLinks {
  std::vector<Index> fluid;        // storage index of the fluid cell x
  std::vector<Index> solid;        // storage index of its solid neighbour x + c_q
  std::vector<std::uint8_t> dir;   // q, from fluid to solid
  std::vector<double> correction;  // -2 w_q rho_w (c_q . u_w) / c_s^2
  std::vector<Vec3> point;         // half-way wall point x + c_q / 2 [lattice coordinates]
  std::size_t size() const { return fluid.size(); }
};

/// Momentum given to a body in one step: force, and torque about the body's reference point;
/// and the mass the body gave the fluid in that step (negative: taken out) [lattice units].
struct WallLoad {
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  double mass = 0.0;
  WallLoad& operator+=(const WallLoad& o) {
    force += o.force;
    torque += o.torque;
    mass += o.mass;
    return *this;
  }
};

/// One slot of a link, read and written as the population it holds (PopulationCodec; the shift
/// is w_q for either slot of the pair q, qbar). Assigning a slot to a slot is deleted: it would
/// copy the address, not the value.
template <class T>
struct SlotRef {
  T* p;
  int q;
  operator double() const { return PopulationCodec<T>::load(*p, q); }
  SlotRef& operator=(double f) {
    *p = PopulationCodec<T>::store(f, q);
    return *this;
  }
  SlotRef& operator=(const SlotRef&) = delete;
};

/// The two slots of link k for the state a step has just produced (the AA rule of the header
/// comment, in one place for every link-wise boundary): `from` holds f_q*(x, t), `to` is where
/// f_qbar(x, t+1) must go.
template <class T>
struct LinkSlots {
  SlotRef<T> from;
  SlotRef<T> to;
};
template <class T>
LinkSlots<T> link_slots(PdfField<T>& pdf, AaState now, const BounceBackLinks& links,
                        std::size_t k) {
  const int q = links.dir[k], o = opposite(q);
  T* const fluid_o = pdf.dir(o) + links.fluid[k];
  T* const solid_q = pdf.dir(q) + links.solid[k];
  if (now == AaState::swapped) return {{fluid_o, q}, {solid_q, q}};
  return {{solid_q, q}, {fluid_o, q}};
}

/// Lists every fluid-to-solid link, one list per body id 1 .. n_bodies (entry k - 1 for body k),
/// in storage order, with zero wall velocity.
std::vector<BounceBackLinks> build_links(const FlagField& flags, int n_bodies);

/// Sets the moving-wall terms of one body's links from its velocity at each link's half-way point;
/// rho_w is the wall density of Ladd's term (the reference density).
void set_wall_velocity(BounceBackLinks& links, const Grid& g, const WallVelocity& u, double rho_w);

/// Applies the links for the state the step has just produced; returns the momentum-exchange
/// force on the body and its torque about `origin` (lattice coordinates), each link's force
/// acting at its half-way point, and the mass given to the fluid [lattice units].
template <class T>
WallLoad apply_bounce_back(PdfField<T>& pdf, AaState now, const BounceBackLinks& links,
                           const Vec3& origin = Vec3::Zero());

}  // namespace lbdem::lbm

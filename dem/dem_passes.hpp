#pragma once
// The two force passes of DemSolver::step, templated on the contact law (one instantiation per law
// combination, chosen once per step by std::visit). Private to dem_solver.cpp.
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "core/thread_ranges.hpp"
#include "dem/dem_solver.hpp"
#include "dem/pair_lanes.hpp"

namespace lbdem::dem {

/// Books one evaluation into the contact's tally, impact record and state bits, and its rates into
/// the block's sums. The contact's own dissipation integrates its damping power with the
/// trapezoidal rule over consecutive steps (second order; the velocity-Verlet energy error is of
/// the same order, docs/physics.md) and adds the energy the cap removed from the springs in the
/// step (sliding, rolling); DemSolver integrates the block sums the same way by mechanism, which
/// equals the sum over contacts (the rule is linear; a contact that starts or ends adds a zero
/// power at the other end).
template <bool kRolling>
inline void book(ContactTally& t, ContactRecord& r, std::uint8_t& state, const ContactForce& c,
                 const ContactGeometry& g, double time, double dt, bool extremes,
                 EnergyRates& rates) {
  const std::uint8_t old = state;
  const bool touch = g.delta > 0;
  std::uint8_t st = 0;
  if (touch) {
    if (!(old & kTouching)) {
      const double vn = g.v_rel.dot(g.n);
      t.e_dissipated = t.p_damping = 0;
      r = ContactRecord{.t_start = time, .vn_impact = vn, .vt_impact = (g.v_rel - vn * g.n).norm()};
      st |= kStarted;
    }
    const double p = c.p_normal_damping + c.p_tangential_damping;
    t.e_dissipated += 0.5 * dt * (t.p_damping + p) + c.e_sliding;
    if constexpr (kRolling) t.e_dissipated += c.e_rolling;
    t.p_damping = p;
    rates.p_normal_damping += c.p_normal_damping;
    rates.p_tangential_damping += c.p_tangential_damping;
    rates.e_sliding += c.e_sliding;
    if constexpr (kRolling) rates.e_rolling += c.e_rolling;
    if (extremes) {  // only the opt-in per-contact rows report them
      r.max_overlap = std::max(r.max_overlap, g.delta);
      r.max_force = std::max(r.max_force, c.fn);
    }
    st |= kTouching | kInteracting;
  } else if (old & kTouching) {
    t.e_dissipated += 0.5 * dt * t.p_damping;
    t.p_damping = 0;
    st |= kEnded;
  }
  if (!touch && c.force.squaredNorm() > 0) st |= kInteracting;
  rates.e_stiffness += c.e_stiffness;
  t.u_elastic = c.u_elastic;
  state = st;
}

// The kernels are flattened: GCC otherwise leaves Eigen's small 3-vector operations as calls in
// these large bodies (measured: about a third of the pair pass in call overhead). Sanitizer builds
// skip it: flattened and instrumented, the twelve law instantiations take many minutes to compile.
#ifdef LBDEM_NO_FLATTEN
#define LBDEM_FLATTEN
#else
#define LBDEM_FLATTEN [[gnu::flatten]]
#endif

/// Velocities predicted to the end of the step, v + dt/2 F_old/m (computed once per particle).
struct Predicted {
  const std::vector<Vec3>& v;
  const std::vector<Vec3>& w;
};

template <class Table>
LBDEM_FLATTEN inline void pair_kernel(const Table& tab, const ParticleArrays& p,
                                      const Predicted& pr, const DemSettings& s, PairList& pl,
                                      double time, std::size_t k, const Vec3& d, double r2,
                                      Vec3& f_i, Vec3& t_i, EnergyRates& rates) {
  using Law = typename Table::law_type;
  const double dt = s.dt;
  const std::uint32_t i = pl.i[k], j = pl.j[k];
  const double ri = p.radius[i], rj = p.radius[j], rs = ri + rj;
  const double dist = std::sqrt(r2);
  ContactGeometry g;
  g.n = d / dist;
  g.delta = rs - dist;
  g.r_star = ri * rj / rs;
  const std::uint32_t slot = pl.jslot[k];
  if (g.delta <= 0) {
    // Apart (cohesion only, or the step a contact ends): no tangential force, so no torque; the
    // torque sums would only add zeros. Skips the eight velocity loads and the kinematics
    // (book() reads v_rel only at the start of a touch).
    g.v_rel = Vec3::Zero();
    const ContactForce c = Law::evaluate_apart(tab.particle(p.material[i], p.material[j]), g,
                                               HistoryRef{pl.history[k], pl.rolling[k]});
    pl.j_force[slot] = -c.force;
    pl.j_torque[slot] = Vec3::Zero();
    book<Law::Rolling::active>(pl.tally[k], pl.record[k], pl.state[k], c, g, time, dt,
                               s.collisions.rows, rates);
    if (pl.state[k] & kInteracting) f_i += c.force;
    return;
  }
  g.m_star = p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j]);
  g.i_star = 0;  // read only by the constant-torque rolling model
  if constexpr (Law::Rolling::active)
    g.i_star = p.inertia[i] * p.inertia[j] / (p.inertia[i] + p.inertia[j]);
  // Velocities predicted to the end of the step (see dem_solver.hpp).
  const Vec3& vi = pr.v[i];
  const Vec3& vj = pr.v[j];
  const Vec3& wi = pr.w[i];
  const Vec3& wj = pr.w[j];
  const double half = 0.5 * std::max(g.delta, 0.0);
  const double ai = ri - half, aj = rj - half;  // centre to contact point
  g.v_rel = vi - vj + (ai * wi + aj * wj).cross(g.n);
  g.w_rel = wi - wj;
  g.v_half = p.v[i] - p.v[j] + (ai * p.omega[i] + aj * p.omega[j]).cross(g.n);
  g.w_half = p.omega[i] - p.omega[j];
  const ContactForce c = Law::evaluate(tab.particle(p.material[i], p.material[j]), g,
                                       HistoryRef{pl.history[k], pl.rolling[k]}, dt);
  const Vec3 tc = g.n.cross(c.ft);
  pl.j_force[slot] = -c.force;
  pl.j_torque[slot] = aj * tc - c.m_roll;
  book<Law::Rolling::active>(pl.tally[k], pl.record[k], pl.state[k], c, g, time, dt,
                             s.collisions.rows, rates);
  if (pl.state[k] & kInteracting) f_i += c.force, t_i += ai * tc + c.m_roll;
}

/// Rows (particles) per block of the energy sums: the passes hand each thread whole blocks, so a
/// block's sum, and the sum over blocks in block order, is the same on any thread count.
inline constexpr std::size_t kEnergyBlock = 256;

inline std::size_t energy_blocks(std::size_t n) {
  return (n + kEnergyBlock - 1) / kEnergyBlock;
}

/// Calls visit(k, d, r2) for each listed pair k of row i that interacts now (within reach, or in a
/// contact the last evaluation left open), in ascending k; d = x_j - x_i (minimum image). The
/// distance test stays in the loop: most listed pairs are in the skin only, and the kernel's large
/// frame is set up just for those that interact.
template <class Visit>
inline void interacting_pairs(const ParticleArrays& p, const PairList& pl, const Domain& dom,
                              double range, std::size_t i, Visit&& visit) {
  const bool per = dom.any_periodic();
  for (std::size_t k = pl.first[i]; k < pl.first[i + 1]; ++k) {
    const std::uint32_t j = pl.j[k];
    Vec3 d = p.x[j] - p.x[i];
    if (per) d = dom.min_image(d);
    const double r2 = d.squaredNorm();
    const double reach = p.radius[i] + p.radius[j] + range;
    if (r2 >= reach * reach && !pl.state[k]) continue;
    visit(k, d, r2);
  }
}

/// The pair pass in lanes (pair_lanes.hpp) over the rows of blocks [b0, b1): the distance loop
/// sends each touching pair to the lanes (the others, a contact that ends this step or a cohesive
/// pair apart, take the scalar kernel), the lanes evaluate the law, and a last loop over the
/// touching pairs, in pair order, books them and adds their forces: to the rows' sums, after the
/// scalar ones, and to the j side.
template <class Table>
void pair_rows_lanes(const Table& tab, const ParticleArrays& p, const Predicted& pr,
                     const DemSettings& s, PairList& pl, double time, RowSums& sums,
                     EnergyRates* rates, std::size_t b0, std::size_t b1) {
  using Law = typename Table::law_type;
  using Rolling = typename Law::Rolling;
  const double range = tab.range, dt = s.dt;
  const Domain& dom = s.domain;
  const bool rows = s.collisions.rows;
  const std::size_t n = p.size();
  thread_local LaneBuffer buf;
  for (std::size_t b = b0; b < b1; ++b) {
    EnergyRates block;
    buf.clear();
    for (std::size_t i = b * kEnergyBlock; i < std::min(n, (b + 1) * kEnergyBlock); ++i) {
      Vec3 f = Vec3::Zero(), t = Vec3::Zero();
      interacting_pairs(p, pl, dom, range, i, [&](std::size_t k, const Vec3& d, double r2) {
        const std::uint32_t j = pl.j[k];
        const double dist = std::sqrt(r2);
        if (p.radius[i] + p.radius[j] - dist > 0)
          buf.push(k, i, j, d, dist);
        else
          pair_kernel(tab, p, pr, s, pl, time, k, d, r2, f, t, block);
      });
      sums.f[i] = f;
      sums.t[i] = t;
    }
    if (!buf.k.empty())
      contact_lanes<typename Law::Normal, Rolling, typename Law::Cohesion>(
          tab.particle(0, 0), p, pr.v, pr.w, pl.history.data(), pl.rolling.data(), dt, buf);
    for (std::size_t q = 0; q < buf.k.size(); ++q) {
      const std::size_t k = std::size_t(buf.k[q]), i = std::size_t(buf.i[q]);
      const Vec3 force(buf.fx[q], buf.fy[q], buf.fz[q]), tc(buf.cx[q], buf.cy[q], buf.cz[q]);
      const std::uint32_t slot = pl.jslot[k];
      pl.j_force[slot] = -force;
      if constexpr (Rolling::active) {
        const Vec3 m_roll(buf.mx[q], buf.my[q], buf.mz[q]);
        pl.j_torque[slot] = buf.aj[q] * tc - m_roll;
        sums.t[i] += buf.ai[q] * tc + m_roll;
      } else {
        pl.j_torque[slot] = buf.aj[q] * tc;
        sums.t[i] += buf.ai[q] * tc;
      }
      sums.f[i] += force;
      // book() for a touching contact, from the lanes' values.
      ContactTally& tl = pl.tally[k];
      ContactRecord& rc = pl.record[k];
      std::uint8_t st = kTouching | kInteracting;
      if (!(pl.state[k] & kTouching)) {
        tl.e_dissipated = tl.p_damping = 0;
        rc = ContactRecord{.t_start = time, .vn_impact = buf.vn[q], .vt_impact = buf.vt[q]};
        st |= kStarted;
      }
      const double pw = buf.p_nd[q] + buf.p_td[q];
      tl.e_dissipated += 0.5 * dt * (tl.p_damping + pw) + buf.e_sl[q];
      if constexpr (Rolling::active) {
        tl.e_dissipated += buf.e_ro[q];
        block.e_rolling += buf.e_ro[q];
      }
      tl.p_damping = pw;
      tl.u_elastic = buf.u_el[q];
      block.p_normal_damping += buf.p_nd[q];
      block.p_tangential_damping += buf.p_td[q];
      block.e_sliding += buf.e_sl[q];
      block.e_stiffness += buf.e_st[q];
      if (rows) {
        rc.max_overlap = std::max(rc.max_overlap, buf.delta[q]);
        rc.max_force = std::max(rc.max_force, buf.fn[q]);
      }
      pl.state[k] = st;
    }
    rates[b] = block;
  }
}

/// The pair pass over the rows of blocks [b0, b1), in a function of its own
/// (core/thread_ranges.hpp: why; pr by value for the same reason: the caller's copy sits on the
/// master thread's stack).
template <class Table>
[[gnu::noinline]] void pair_rows(const Table& tab, const ParticleArrays& p, const Predicted pr,
                                 const DemSettings& s, PairList& pl, double time, RowSums& sums,
                                 EnergyRates* rates, std::size_t b0, std::size_t b1) {
  using Law = typename Table::law_type;
  // A law with a lane form, one parameter set (the lanes take it as constants), and indices the
  // lanes' 32-bit gathers reach (4 per pair, 3 per particle).
  if constexpr (has_lane_form<Law>())
    if (tab.n_materials == 1 && pl.size() < (std::size_t(1) << 29) &&
        p.size() < (std::size_t(1) << 29))
      return pair_rows_lanes(tab, p, pr, s, pl, time, sums, rates, b0, b1);
  const double range = tab.range;
  const Domain& dom = s.domain;
  const std::size_t n = p.size();
  for (std::size_t b = b0; b < b1; ++b) {
    EnergyRates block;
    for (std::size_t i = b * kEnergyBlock; i < std::min(n, (b + 1) * kEnergyBlock); ++i) {
      Vec3 f = Vec3::Zero(), t = Vec3::Zero();
      interacting_pairs(p, pl, dom, range, i, [&](std::size_t k, const Vec3& d, double r2) {
        pair_kernel(tab, p, pr, s, pl, time, k, d, r2, f, t, block);
      });
      sums.f[i] = f;
      sums.t[i] = t;
    }
    rates[b] = block;
  }
}

/// Pairs are taken row by row (all pairs with the same i in one thread, in ascending j), so the
/// forces on i are summed right here in a fixed order; the particle pass gathers only the j side.
/// rates: one EnergyRates per block of kEnergyBlock rows.
template <class Table>
void run_pair_pass(const Table& tab, const ParticleArrays& p, const Predicted& pr,
                   const DemSettings& s, PairList& pl, double time, RowSums& sums,
                   std::vector<EnergyRates>& rates) {
  const std::size_t n = p.size();
  sums.f.resize(n);
  sums.t.resize(n);
  rates.assign(energy_blocks(n), EnergyRates{});
  EnergyRates* r = rates.data();
  for_thread_ranges(rates.size(), [&](std::size_t b0, std::size_t b1) {
    pair_rows(tab, p, pr, s, pl, time, sums, r, b0, b1);
  });
}

/// Contact of particle k with wall entry e, given where the wall is seen from the centre.
template <class Law, class Params>
void wall_contact(const Params& prm, const ParticleArrays& p, std::size_t k, const Vec3& vk,
                  const Vec3& wk, const Vec3& vh, const Vec3& wh, const Vec3& n, double dist,
                  const Vec3& wall_velocity, const Vec3& origin, WallContactList& wc, std::size_t e,
                  double time, double dt, bool rows, Vec3& f, Vec3& tq, EnergyRates& rates) {
  ContactGeometry g;
  g.n = n;
  g.delta = p.radius[k] - dist;
  g.r_star = p.radius[k];
  g.m_star = p.mass[k];
  g.i_star = p.inertia[k];
  const double a = p.radius[k] - std::max(g.delta, 0.0);
  g.v_rel = vk + a * wk.cross(n) - wall_velocity;
  g.w_rel = wk;
  g.v_half = vh + a * wh.cross(n) - wall_velocity;
  g.w_half = wh;
  const ContactForce c =
      Law::evaluate(prm, g, HistoryRef{wc.history[e].spring, wc.history[e].rolling}, dt);
  const Vec3 point = p.x[k] + a * n;
  f += c.force;
  tq += a * n.cross(c.ft) + c.m_roll;
  wc.force[e] = c.force;
  wc.contact_point[e] = point;
  // The rolling torque's reaction on the wall is included; its work on a rotating wall is not
  // (it needs the wall's spin, and mu_r is small).
  wc.wall_torque[e] = (point - origin).cross(-c.force) - c.m_roll;
  wc.power[e] = c.force.dot(wall_velocity);
  book<Law::Rolling::active>(wc.tally[e], wc.record[e], wc.state[e], c, g, time, dt, rows, rates);
}

template <class Table>
LBDEM_FLATTEN inline void particle_kernel(const Table& tab, ParticleArrays& p, const Predicted& pr,
                                          const RowSums& sums, const DemSettings& s,
                                          const std::vector<Wall>& walls, const PairList& pl,
                                          WallContactList& wc, double time, std::size_t k,
                                          EnergyRates& rates) {
  using Law = typename Table::law_type;
  const double dt = s.dt, h = 0.5 * dt, range = tab.range;
  const Vec3& vk = pr.v[k];
  const Vec3& wk = pr.w[k];
  const Vec3 vh = p.v[k], wh = p.omega[k];
  Vec3 f = p.mass[k] * s.gravity + p.external[k];
  Vec3 tq = Vec3::Zero();
  // Walls first, in entry order (sorted by wall, then triangle).
  for (std::size_t e = wc.first[k]; e < wc.first[k + 1];) {
    const Wall& w = walls[wc.wall[e]];
    const auto& prm = tab.wall(p.material[k], w.material);
    if (const auto* mesh = std::get_if<MeshWall>(&w.shape)) {
      std::size_t e1 = e;
      while (e1 < wc.first[k + 1] && wc.wall[e1] == wc.wall[e]) ++e1;
      thread_local std::vector<MeshHit> hits;
      thread_local std::vector<std::size_t> hit_entry;
      thread_local std::vector<char> keep, kept_entry;
      hits.clear(), hit_entry.clear();
      const double reach = p.radius[k] + range;
      for (std::size_t q = e; q < e1; ++q) {
        const MeshClosest c = mesh->closest(wc.tri[q], p.x[k]);
        if (c.dist2 < reach * reach && c.dist2 > 0)
          hits.push_back({wc.tri[q], c}), hit_entry.push_back(q);
      }
      select_mesh_contacts(mesh->mesh, hits, keep);
      kept_entry.assign(e1 - e, 0);
      for (std::size_t m = 0; m < hits.size(); ++m)
        if (keep[m]) kept_entry[hit_entry[m] - e] = 1;
      // A contact that moves onto a neighbouring triangle keeps its history (flat meshes behave
      // like the analytic plane): a new kept entry inherits from a vanished one of this mesh.
      for (std::size_t q = e; q < e1; ++q) {
        if (!kept_entry[q - e] || wc.state[q]) continue;
        for (std::size_t r = e; r < e1; ++r)
          if (!kept_entry[r - e] && (wc.state[r] & kInteracting)) {
            wc.history[q] = wc.history[r], wc.tally[q] = wc.tally[r];
            wc.record[q] = wc.record[r], wc.state[q] = wc.state[r];
            wc.history[r] = ContactHistory{}, wc.tally[r] = ContactTally{};
            wc.record[r] = ContactRecord{}, wc.state[r] = 0;
            break;
          }
      }
      for (std::size_t m = 0; m < hits.size(); ++m) {
        if (!keep[m]) continue;
        const std::size_t q = hit_entry[m];
        const Vec3 d = hits[m].closest.point - p.x[k];
        const double dist = std::sqrt(hits[m].closest.dist2);
        wall_contact<Law>(prm, p, k, vk, wk, vh, wh, d / dist, dist,
                          mesh->motion.velocity_at(hits[m].closest.point, time), w.torque_origin,
                          wc, q, time, dt, s.collisions.rows, f, tq, rates);
      }
      for (std::size_t q = e; q < e1; ++q)  // entries that stopped interacting: close them
        if (!kept_entry[q - e] && wc.state[q])
          wall_contact<Law>(prm, p, k, vk, wk, vh, wh, Vec3::UnitZ(), 1e300, Vec3::Zero(),
                            w.torque_origin, wc, q, time, dt, s.collisions.rows, f, tq, rates);
      e = e1;
    } else {
      const WallPoint wp = analytic_wall_point(w, p.x[k], time);
      if (p.radius[k] - wp.dist > -range || wc.state[e])
        wall_contact<Law>(prm, p, k, vk, wk, vh, wh, wp.n, std::min(wp.dist, 1e300),
                          wp.wall_velocity, w.torque_origin, wc, e, time, dt, s.collisions.rows, f,
                          tq, rates);
      ++e;
    }
  }
  f += sums.f[k];
  tq += sums.t[k];
  for (std::uint32_t r = pl.jfirst[k]; r < pl.jfirst[k + 1]; ++r)
    f += pl.j_force[r], tq += pl.j_torque[r];
  p.force[k] = f;
  p.torque[k] = tq;
  p.v[k] += (h / p.mass[k]) * f;
  p.omega[k] += (h / p.inertia[k]) * tq;
}

/// The particle pass over the particles of blocks [b0, b1), as pair_rows.
template <class Table>
[[gnu::noinline]] void particle_range(const Table& tab, ParticleArrays& p, const Predicted pr,
                                      const RowSums& sums, const DemSettings& s,
                                      const std::vector<Wall>& walls, const PairList& pl,
                                      WallContactList& wc, double time, EnergyRates* rates,
                                      std::size_t b0, std::size_t b1) {
  const std::size_t n = p.size();
  for (std::size_t b = b0; b < b1; ++b) {
    EnergyRates block;
    for (std::size_t k = b * kEnergyBlock; k < std::min(n, (b + 1) * kEnergyBlock); ++k)
      particle_kernel(tab, p, pr, sums, s, walls, pl, wc, time, k, block);
    rates[b] = block;
  }
}

/// rates: the wall contacts' EnergyRates, one per block of kEnergyBlock particles.
template <class Table>
void run_particle_pass(const Table& tab, ParticleArrays& p, const Predicted& pr,
                       const RowSums& sums, const DemSettings& s, const std::vector<Wall>& walls,
                       const PairList& pl, WallContactList& wc, double time,
                       std::vector<EnergyRates>& rates) {
  rates.assign(energy_blocks(p.size()), EnergyRates{});
  EnergyRates* r = rates.data();
  for_thread_ranges(rates.size(), [&](std::size_t b0, std::size_t b1) {
    particle_range(tab, p, pr, sums, s, walls, pl, wc, time, r, b0, b1);
  });
}

}  // namespace lbdem::dem

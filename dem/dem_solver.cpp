#include "dem/dem_solver.hpp"

#include "core/phase_timer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/deterministic_sum.hpp"
#include "core/error.hpp"
#include "dem/dem_passes.hpp"

namespace lbdem::dem {

DemSolver::DemSolver(const DemSettings& s, std::vector<Material> materials)
    : s_(s), materials_(std::move(materials)), law_(make_law_table(s.contact, materials_)) {
  if (materials_.empty())
    throw InputError("materials", "[]", "no material defined", "add a [[materials]] table");
  stats_.setup(s_.collisions, s_.domain);
}

double DemSolver::interaction_range() const {
  return std::visit([](const auto& t) { return t.range; }, law_);
}

void DemSolver::add_particle(const Vec3& x, const Vec3& v, double radius, int material) {
  const Material& m = materials_.at(material);
  p_.add(x, v, Vec3::Zero(), radius, m.density, material, next_id_++);
  const std::size_t k = p_.size() - 1;
  p_.force[k] = p_.mass[k] * s_.gravity;
  max_radius_ = std::max(max_radius_, radius);
  if (step_ > 0 || t_ > 0)
    inserted_ += 0.5 * p_.mass[k] * v.squaredNorm() - p_.mass[k] * s_.gravity.dot(x);
  need_rebuild_ = true;
}

void DemSolver::remove_particles(const std::vector<std::uint32_t>& idx) {
  remove_flag_.resize(p_.size(), 0);
  for (auto k : idx) remove_flag_[k] = 1;
  need_rebuild_ = true;
}

int DemSolver::add_wall(Wall w) {
  if (w.material < 0 || w.material >= static_cast<int>(materials_.size()))
    throw InputError("walls." + w.name + ".material", std::to_string(w.material),
                     "no such material", "name one of the [[materials]]");
  walls_.push_back(std::move(w));
  if (auto* m = std::get_if<MeshWall>(&walls_.back().shape)) m->update(t_);
  need_rebuild_ = true;
  return static_cast<int>(walls_.size()) - 1;
}

void DemSolver::update_walls() {
  for (auto& w : walls_)
    if (auto* m = std::get_if<MeshWall>(&w.shape); m && m->motion.moving()) m->update(t_);
}

double DemSolver::wall_displacement() const {
  double d2 = 0;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    if (const auto* m = std::get_if<MeshWall>(&walls_[w].shape); m && m->motion.moving()) {
      for (std::size_t k = 0; k < m->current.size(); ++k)
        d2 = std::max(d2, (m->current[k] - wall_ref_[w][k]).squaredNorm());
    } else if (const auto* b = std::get_if<BoxWall>(&walls_[w].shape); b && b->motion.moving()) {
      const auto c = b->corners(t_);
      for (std::size_t k = 0; k < c.size(); ++k)
        d2 = std::max(d2, (c[k] - wall_ref_[w][k]).squaredNorm());
    }
  }
  return std::sqrt(d2);
}

void DemSolver::step() {
  const double dt = s_.dt, h = 0.5 * dt;
  const std::size_t n = p_.size();
  PhaseLap lap;
  // Half kick, drift, and the velocities predicted to the end of the step (v + dt/2 F_old/m, used
  // by the dashpots), in one pass; a rebuild reorders particles, so it recomputes the predictions.
  v_pred_.resize(n);
  w_pred_.resize(n);
  double max_d2 = 0;
  std::size_t first_bad = n;  // the watchdog: lowest index of an unsound particle
  const double limit2 = speed_limit2_;
#pragma omp parallel for schedule(static) reduction(max : max_d2) reduction(min : first_bad)
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 dv = (h / p_.mass[k]) * p_.force[k], dw = (h / p_.inertia[k]) * p_.torque[k];
    p_.v[k] += dv;
    p_.omega[k] += dw;
    p_.x[k] += dt * p_.v[k];
    v_pred_[k] = p_.v[k] + dv;
    w_pred_[k] = p_.omega[k] + dw;
    if (k < x_ref_.size()) max_d2 = std::max(max_d2, (p_.x[k] - x_ref_[k]).squaredNorm());
    // Read-only, so the step's results do not change; a NaN fails both comparisons.
    if (!(p_.v[k].squaredNorm() <= limit2) ||
        !std::isfinite(p_.x[k].sum() + p_.omega[k].sum() + p_.force[k].sum() + p_.torque[k].sum()))
      first_bad = std::min(first_bad, k);
  }
  t_ = static_cast<double>(step_ + 1) * dt;  // from the step count: no drift over 1e8 steps
  ++step_;
  if (first_bad < n) {
    // Serial, once: the state is not stepped further (a NaN position would reach the cell list).
    const std::size_t k = first_bad;
    DemAlarm a;
    a.step = step_, a.time = t_, a.id = p_.id[k];
    a.x = p_.x[k], a.v = p_.v[k], a.omega = p_.omega[k];
    a.force = p_.force[k], a.torque = p_.torque[k];
    a.finite = a.x.allFinite() && a.v.allFinite() && a.omega.allFinite() && a.force.allFinite() &&
               a.torque.allFinite();
    if (!alarm_) alarm_ = a;
    return;
  }
  update_walls();
  lap.to(Phase::dem_integration);
  const double max_d = std::sqrt(max_d2);
  if (need_rebuild_ || 2 * max_d > s_.skin || max_d + wall_displacement() > s_.skin) {
    rebuild();
    const std::size_t np = p_.size();
    v_pred_.resize(np);
    w_pred_.resize(np);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < np; ++k) {
      v_pred_[k] = p_.v[k] + (h / p_.mass[k]) * p_.force[k];
      w_pred_[k] = p_.omega[k] + (h / p_.inertia[k]) * p_.torque[k];
    }
    lap.to(Phase::dem_neighbour_search);
  }
  std::visit(
      [&](const auto& table) {
        pair_pass(table);
        lap.to(Phase::dem_pair_contacts);
        particle_pass(table);
        lap.to(Phase::dem_walls_and_kick);
      },
      law_);
  event_scan();
  book_energy();
  sum_wall_loads();
  if (track_external_) {
    const double power = deterministic_sum(
        p_.size(), [&](std::size_t k) { return p_.external[k].dot(p_.v[k]); }, 0.0);
    external_work_ += 0.5 * dt * (external_power_prev_ + power);  // trapezoidal rule
    external_power_prev_ = power;
  }
  lap.to(Phase::dem_bookkeeping);
}

template <class Table>
void DemSolver::pair_pass(const Table& t) {
  run_pair_pass(t, p_, Predicted{v_pred_, w_pred_}, s_, pairs_, t_, row_sums_, pair_rates_);
}

template <class Table>
void DemSolver::particle_pass(const Table& t) {
  run_particle_pass(t, p_, Predicted{v_pred_, w_pred_}, row_sums_, s_, walls_, pairs_, wc_, t_,
                    wall_rates_);
}

void DemSolver::event_scan() {
  const auto scan = [&](std::vector<std::uint8_t>& state, std::vector<ContactTally>& tally,
                        std::vector<ContactRecord>& record, bool wall, auto&& ids, auto&& where) {
    for (std::size_t k = 0; k < state.size(); ++k) {
      const std::uint8_t st = state[k];
      if (!(st & (kStarted | kEnded))) continue;
      if (st & kStarted) stats_.on_start(wall, record[k].vn_impact, record[k].vt_impact);
      if (st & kEnded) {
        const auto [a, b] = ids(k);
        stats_.on_end(tally[k], record[k], t_, a, b, where(k));
        tally[k].e_dissipated = 0;  // u_elastic stays: cohesion may hold energy after the touch
        record[k] = ContactRecord{};
      }
      state[k] = st & (kInteracting | kTouching);
    }
  };
  scan(
      pairs_.state, pairs_.tally, pairs_.record, false,
      [&](std::size_t k) {
        return std::pair{p_.id[pairs_.i[k]], p_.id[pairs_.j[k]]};
      },
      [&](std::size_t k) { return Vec3(0.5 * (p_.x[pairs_.i[k]] + p_.x[pairs_.j[k]])); });
  scan(
      wc_.state, wc_.tally, wc_.record, true,
      [&](std::size_t k) {
        return std::pair{p_.id[wc_.particle[k]], std::int64_t(-1 - wc_.wall[k])};
      },
      [&](std::size_t k) { return wc_.contact_point[k]; });
}

void DemSolver::book_energy() {
  // The step's rates over all contacts, the pair blocks then the wall blocks, in block order.
  EnergyRates r;
  for (const auto* v : {&pair_rates_, &wall_rates_})
    for (const EnergyRates& b : *v) {
      r.p_normal_damping += b.p_normal_damping;
      r.p_tangential_damping += b.p_tangential_damping;
      r.e_sliding += b.e_sliding;
      r.e_rolling += b.e_rolling;
      r.e_stiffness += b.e_stiffness;
    }
  const double h = 0.5 * s_.dt;  // trapezoidal rule over the dashpots' total powers
  stats_.add_dissipated(h * (p_normal_damping_prev_ + r.p_normal_damping),
                        h * (p_tangential_damping_prev_ + r.p_tangential_damping), r.e_sliding,
                        r.e_rolling);
  p_normal_damping_prev_ = r.p_normal_damping;
  p_tangential_damping_prev_ = r.p_tangential_damping;
  stiffness_energy_ += r.e_stiffness;
}

void DemSolver::sum_wall_loads() {
  const std::size_t nw = walls_.size();
  if (nw == 0) return;
  // Fixed blocks of entries (independent of the thread count), each with its partial per wall:
  // F (3), T (3), then the total power; the partials are added serially in block order.
  const std::size_t width = 6 * nw + 1, ne = wc_.size();
  const std::size_t nb = std::max<std::size_t>(1, (ne + kSumBlock - 1) / kSumBlock);
  wall_partials_.assign(nb * width, 0.0);  // reuses its capacity: no allocation per step
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    double* v = wall_partials_.data() + b * width;
    for (std::size_t k = b * kSumBlock; k < std::min(ne, (b + 1) * kSumBlock); ++k) {
      if (!(wc_.state[k] & kInteracting)) continue;
      const std::size_t w = wc_.wall[k];
      for (int a = 0; a < 3; ++a)
        v[6 * w + a] -= wc_.force[k][a], v[6 * w + 3 + a] += wc_.wall_torque[k][a];
      v[6 * nw] += wc_.power[k];
    }
  }
  for (std::size_t b = 1; b < nb; ++b)
    for (std::size_t c = 0; c < width; ++c) wall_partials_[c] += wall_partials_[b * width + c];
  const double* tot = wall_partials_.data();
  for (std::size_t w = 0; w < nw; ++w) {
    walls_[w].force = Vec3(tot[6 * w], tot[6 * w + 1], tot[6 * w + 2]);
    walls_[w].torque = Vec3(tot[6 * w + 3], tot[6 * w + 4], tot[6 * w + 5]);
  }
  const double power = tot[6 * nw];
  wall_work_ += 0.5 * s_.dt * (wall_power_prev_ + power);  // trapezoidal rule
  wall_power_prev_ = power;
}

std::size_t DemSolver::contacts_pp() const {
  return static_cast<std::size_t>(std::count_if(pairs_.state.begin(), pairs_.state.end(),
                                                [](auto s) { return s & kTouching; }));
}
std::size_t DemSolver::contacts_pw() const {
  return static_cast<std::size_t>(
      std::count_if(wc_.state.begin(), wc_.state.end(), [](auto s) { return s & kTouching; }));
}

std::vector<std::int32_t> DemSolver::coordination() const {
  std::vector<std::int32_t> c(p_.size(), 0);
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    if (pairs_.state[k] & kTouching) ++c[pairs_.i[k]], ++c[pairs_.j[k]];
  return c;
}

EnergyTotals DemSolver::energy() const {
  EnergyTotals e;
  const std::size_t n = p_.size();
  e.kinetic_translational = deterministic_sum(
      n, [&](std::size_t k) { return 0.5 * p_.mass[k] * p_.v[k].squaredNorm(); }, 0.0);
  e.kinetic_rotational = deterministic_sum(
      n, [&](std::size_t k) { return 0.5 * p_.inertia[k] * p_.omega[k].squaredNorm(); }, 0.0);
  e.potential = deterministic_sum(
      n, [&](std::size_t k) { return -p_.mass[k] * s_.gravity.dot(p_.x[k]); }, 0.0);
  const auto stored = [](const std::vector<ContactTally>& t) {
    return deterministic_sum(
        t.size(), [&](std::size_t k) { return t[k].u_elastic; }, 0.0);
  };
  e.elastic = stored(pairs_.tally) + stored(wc_.tally);
  const double* d = stats_.dissipated();
  e.normal_damping = d[0];
  e.tangential_damping = d[1];
  e.sliding = d[2];
  e.rolling = d[3];
  e.stiffness_change = stiffness_energy_;
  e.wall_work = wall_work_;
  e.external_work = external_work_;
  e.inserted = inserted_;
  e.removed = removed_;
  return e;
}

}  // namespace lbdem::dem

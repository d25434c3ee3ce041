// Checkpoint of the complete DEM state: a resumed run continues bitwise as if it had never stopped,
// so everything that influences later steps is saved, the neighbour lists included.
#include <cstring>
#include <stdexcept>

#include "core/h5.hpp"
#include "dem/dem_solver.hpp"

namespace lbdem::dem {

namespace {
// All are plain doubles without implicit padding, so a checkpoint holds no indeterminate bytes.
constexpr std::size_t kTallyWidth = 3, kRow = 8;  // a checkpoint row: the tally, then the record
static_assert(sizeof(ContactHistory) == 8 * sizeof(double) &&
              sizeof(SpringHistory) == 4 * sizeof(double) &&
              sizeof(RollingHistory) == 4 * sizeof(double) &&
              sizeof(ContactTally) == kTallyWidth * sizeof(double) &&
              sizeof(ContactTally) + sizeof(ContactRecord) == kRow * sizeof(double));

template <class T>
std::vector<double> flatten(const std::vector<T>& v) {
  std::vector<double> out(v.size() * sizeof(T) / sizeof(double));
  if (!v.empty()) std::memcpy(out.data(), v.data(), v.size() * sizeof(T));
  return out;
}
template <class T>
std::vector<T> unflatten(const std::vector<double>& d) {
  std::vector<T> out(d.size() * sizeof(double) / sizeof(T));
  if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), d.data(), out.size() * sizeof(T));
  return out;
}
// A contact's tally and impact record are stored as one row of 8 doubles.
std::vector<double> flatten(const std::vector<ContactTally>& t,
                            const std::vector<ContactRecord>& r) {
  if (t.size() != r.size())
    throw std::logic_error("contact tally and record arrays differ in length");
  std::vector<double> out(t.size() * kRow);
  for (std::size_t k = 0; k < t.size(); ++k) {
    std::memcpy(&out[k * kRow], &t[k], sizeof(ContactTally));
    std::memcpy(&out[k * kRow + kTallyWidth], &r[k], sizeof(ContactRecord));
  }
  return out;
}
void unflatten(const std::vector<double>& d, std::vector<ContactTally>& t,
               std::vector<ContactRecord>& r) {
  const std::size_t n = d.size() / kRow;
  t.assign(n, {}), r.assign(n, {});
  for (std::size_t k = 0; k < n; ++k) {
    std::memcpy(static_cast<void*>(&t[k]), &d[k * kRow], sizeof(ContactTally));
    std::memcpy(static_cast<void*>(&r[k]), &d[k * kRow + kTallyWidth], sizeof(ContactRecord));
  }
}
template <class A, class B>
std::vector<B> cast(const std::vector<A>& a) {
  return std::vector<B>(a.begin(), a.end());
}
}  // namespace

void DemSolver::save(H5Out& f) const {
  f.group("/dem");
  f.attr("layout_version", std::int64_t(kCheckpointLayout), "/dem");
  f.attr("time_s", t_, "/dem");
  f.attr("step", step_, "/dem");
  f.attr("rebuilds", rebuilds_, "/dem");
  f.attr("lost", lost_, "/dem");
  f.attr("next_id", next_id_, "/dem");
  f.attr("need_rebuild", std::int64_t(need_rebuild_), "/dem");
  f.write("/dem/accounts",
          std::vector<double>{stiffness_energy_, wall_work_, wall_power_prev_, inserted_, removed_,
                              mass_removed_, max_radius_, external_work_, external_power_prev_,
                              double(track_external_), p_normal_damping_prev_,
                              p_tangential_damping_prev_});
  f.write("/dem/x", p_.x);
  f.write("/dem/v", p_.v);
  f.write("/dem/omega", p_.omega);
  f.write("/dem/force", p_.force);
  f.write("/dem/torque", p_.torque);
  f.write("/dem/external", p_.external);
  f.write("/dem/radius", p_.radius);
  f.write("/dem/mass", p_.mass);
  f.write("/dem/inertia", p_.inertia);
  f.write("/dem/material", p_.material);
  f.write("/dem/id", p_.id);
  f.write("/dem/x_ref", x_ref_);
  f.write("/dem/remove_flag", remove_flag_);
  f.write("/dem/pairs_i", cast<std::uint32_t, std::int64_t>(pairs_.i));
  f.write("/dem/pairs_j", cast<std::uint32_t, std::int64_t>(pairs_.j));
  f.write("/dem/pairs_history", flatten(pairs_.history));
  f.write("/dem/pairs_rolling", flatten(pairs_.rolling));
  f.write("/dem/pairs_tally", flatten(pairs_.tally, pairs_.record));
  f.write("/dem/pairs_state", pairs_.state);
  f.write("/dem/pairs_first", cast<std::uint32_t, std::int64_t>(pairs_.first));
  f.write("/dem/wc_particle", cast<std::uint32_t, std::int64_t>(wc_.particle));
  f.write("/dem/wc_wall", cast<std::uint16_t, std::int64_t>(wc_.wall));
  f.write("/dem/wc_tri", cast<std::int32_t, std::int64_t>(wc_.tri));
  f.write("/dem/wc_history", flatten(wc_.history));
  f.write("/dem/wc_tally", flatten(wc_.tally, wc_.record));
  f.write("/dem/wc_state", wc_.state);
  f.write("/dem/wc_first", cast<std::uint32_t, std::int64_t>(wc_.first));
  for (std::size_t w = 0; w < wall_ref_.size(); ++w)
    f.write("/dem/wall_ref" + std::to_string(w), wall_ref_[w]);
  std::vector<double> loads;
  for (const auto& w : walls_)
    loads.insert(loads.end(),
                 {w.force[0], w.force[1], w.force[2], w.torque[0], w.torque[1], w.torque[2]});
  f.write("/dem/wall_loads", loads);
  stats_.save(f, "/dem/collisions");
}

// The loaded particle and pair arrays agree with each other and with this solver's materials: a
// checkpoint of another run fails here, not in a step that indexes past them.
void DemSolver::check_loaded() const {
  const std::size_t n = p_.x.size();
  for (const std::size_t m :
       {p_.v.size(), p_.omega.size(), p_.force.size(), p_.torque.size(), p_.external.size(),
        p_.radius.size(), p_.mass.size(), p_.inertia.size(), p_.material.size(), p_.id.size()})
    if (m != n)
      throw std::runtime_error("checkpoint is inconsistent: particle arrays differ in length");
  for (const auto m : p_.material)
    if (m < 0 || std::size_t(m) >= materials_.size())
      throw std::runtime_error("checkpoint does not fit this run: material index " +
                               std::to_string(m) + ", this run has " +
                               std::to_string(materials_.size()) + " materials");
  if (pairs_.j.size() != pairs_.size())
    throw std::runtime_error("checkpoint is inconsistent: pair arrays differ in length");
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    if (pairs_.i[k] >= n || pairs_.j[k] >= n)
      throw std::runtime_error("checkpoint is inconsistent: a contact names a particle past " +
                               std::to_string(n));
}

void DemSolver::load(const H5In& f) {
  if (!f.has("/dem") || f.attr_int("layout_version", "/dem") != kCheckpointLayout)
    throw std::runtime_error("checkpoint written by an incompatible lbdem build (layout " +
                             std::to_string(kCheckpointLayout) +
                             " expected); rerun from the start");
  t_ = f.attr_double("time_s", "/dem");
  step_ = f.attr_int("step", "/dem");
  rebuilds_ = f.attr_int("rebuilds", "/dem");
  lost_ = f.attr_int("lost", "/dem");
  next_id_ = f.attr_int("next_id", "/dem");
  need_rebuild_ = f.attr_int("need_rebuild", "/dem") != 0;
  const auto acc = f.doubles("/dem/accounts");
  if (acc.size() != 12) throw std::runtime_error("checkpoint is inconsistent: /dem/accounts");
  stiffness_energy_ = acc[0], wall_work_ = acc[1], wall_power_prev_ = acc[2], inserted_ = acc[3];
  removed_ = acc[4], mass_removed_ = acc[5], max_radius_ = acc[6];
  external_work_ = acc[7], external_power_prev_ = acc[8], track_external_ = acc[9] != 0;
  p_normal_damping_prev_ = acc[10], p_tangential_damping_prev_ = acc[11];
  p_.x = f.vec3s("/dem/x");
  p_.v = f.vec3s("/dem/v");
  p_.omega = f.vec3s("/dem/omega");
  p_.force = f.vec3s("/dem/force");
  p_.torque = f.vec3s("/dem/torque");
  p_.external = f.vec3s("/dem/external");
  p_.radius = f.doubles("/dem/radius");
  p_.mass = f.doubles("/dem/mass");
  p_.inertia = f.doubles("/dem/inertia");
  p_.material = f.int32s("/dem/material");
  p_.id = f.int64s("/dem/id");
  x_ref_ = f.vec3s("/dem/x_ref");
  remove_flag_ = f.uint8s("/dem/remove_flag");
  const auto pi = f.int64s("/dem/pairs_i");
  pairs_.resize(pi.size());
  pairs_.i = cast<std::int64_t, std::uint32_t>(pi);
  pairs_.j = cast<std::int64_t, std::uint32_t>(f.int64s("/dem/pairs_j"));
  pairs_.history = unflatten<SpringHistory>(f.doubles("/dem/pairs_history"));
  pairs_.rolling = unflatten<RollingHistory>(f.doubles("/dem/pairs_rolling"));
  unflatten(f.doubles("/dem/pairs_tally"), pairs_.tally, pairs_.record);
  pairs_.state = f.uint8s("/dem/pairs_state");
  if (pairs_.history.size() != pi.size() || pairs_.rolling.size() != pi.size() ||
      pairs_.tally.size() != pi.size() || pairs_.state.size() != pi.size())
    throw std::runtime_error("checkpoint is inconsistent: pair arrays differ in length");
  pairs_.first = cast<std::int64_t, std::uint32_t>(f.int64s("/dem/pairs_first"));
  check_loaded();
  pairs_.build_transpose(p_.size());
  const auto wp = f.int64s("/dem/wc_particle");
  wc_.resize(wp.size());
  wc_.particle = cast<std::int64_t, std::uint32_t>(wp);
  wc_.wall = cast<std::int64_t, std::uint16_t>(f.int64s("/dem/wc_wall"));
  wc_.tri = cast<std::int64_t, std::int32_t>(f.int64s("/dem/wc_tri"));
  wc_.history = unflatten<ContactHistory>(f.doubles("/dem/wc_history"));
  unflatten(f.doubles("/dem/wc_tally"), wc_.tally, wc_.record);
  wc_.state = f.uint8s("/dem/wc_state");
  if (wc_.history.size() != wp.size() || wc_.tally.size() != wp.size() ||
      wc_.state.size() != wp.size() || wc_.wall.size() != wp.size() || wc_.tri.size() != wp.size())
    throw std::runtime_error("checkpoint is inconsistent: wall-contact arrays differ in length");
  wc_.first = cast<std::int64_t, std::uint32_t>(f.int64s("/dem/wc_first"));
  for (std::size_t k = 0; k < wc_.size(); ++k)
    if (wc_.particle[k] >= p_.size() || wc_.wall[k] >= walls_.size())
      throw std::runtime_error(
          "checkpoint does not fit this run: a wall contact names particle " +
          std::to_string(wc_.particle[k]) + " of " + std::to_string(p_.size()) + " or wall " +
          std::to_string(wc_.wall[k]) + " of " + std::to_string(walls_.size()));
  wall_ref_.assign(walls_.size(), {});
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const std::string name = "/dem/wall_ref" + std::to_string(w);
    if (f.has(name)) wall_ref_[w] = f.vec3s(name);
  }
  const auto loads = f.doubles("/dem/wall_loads");
  for (std::size_t w = 0; w < walls_.size() && 6 * w + 5 < loads.size(); ++w) {
    walls_[w].force = Vec3(loads[6 * w], loads[6 * w + 1], loads[6 * w + 2]);
    walls_[w].torque = Vec3(loads[6 * w + 3], loads[6 * w + 4], loads[6 * w + 5]);
  }
  update_walls();
  for (auto& w : walls_)
    if (auto* m = std::get_if<MeshWall>(&w.shape)) m->update(t_);
  stats_.load(f, "/dem/collisions");
}

}  // namespace lbdem::dem

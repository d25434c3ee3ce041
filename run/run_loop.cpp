#include "run/run_loop.hpp"

#include "core/phase_timer.hpp"

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <variant>

#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/progress.hpp"
#include "core/time_series.hpp"
#include "core/timer.hpp"
#include "run/checkpoint_check.hpp"
#include "run/run_manifest.hpp"
#include "run/xdmf.hpp"

namespace lbdem::run {

namespace fs = std::filesystem;

namespace {
// Set by SIGINT/SIGTERM: the loop then writes a checkpoint at the current step and stops, so an
// interrupted run loses nothing and resumes exactly.
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void on_stop_signal(int sig) {
  g_stop_signal = sig;
}
}  // namespace

bool stop_requested() {
  return g_stop_signal != 0;
}

namespace {
// A positive time [s] at `key`, `fallback` if absent, or infinity for the string "never".
double seconds_or_never(const Config& out, const std::string& key, double fallback,
                        const std::string& fix) {
  if (!out.is_string(key)) return out.get(key, fallback, Range::positive(fix));
  if (const std::string v = out.get_string(key, ""); v != "never")
    throw InputError(out.path(key), "\"" + v + "\"", "expected a time in s, or \"never\"", fix);
  return std::numeric_limits<double>::infinity();
}
}  // namespace

OutputSettings OutputSettings::from(const Config& run, const Config& out) {
  OutputSettings o;
  o.end_time = run.require("end_time", Range::positive("give the simulated end time in seconds"));
  o.interval =
      out.get("interval", o.end_time / 200, Range::positive("give the time-series interval in s"));
  o.snapshot_interval = out.get("snapshot_interval", o.end_time / 10,
                                Range::positive("give the snapshot interval in s"));
  // Checkpoints are what a killed run resumes from: switched off only by name ("never", which the
  // run command warns about), never by a 0 that may be a slip. "never" for the simulated interval
  // turns the wall-time ones off too; the wall-time interval bounds the work lost where the
  // simulated one takes hours.
  o.checkpoint_interval = seconds_or_never(
      out, "checkpoint_interval", o.end_time / 4,
      "give the checkpoint interval in s, e.g. run.end_time / 4 (the default); \"never\" "
      "switches periodic checkpoints off");
  o.checkpoint_wall_interval =
      std::isinf(o.checkpoint_interval)
          ? o.checkpoint_interval
          : seconds_or_never(out, "checkpoint_wall_interval", 900.0,
                             "give the wall time between checkpoints in s, e.g. 900 (the "
                             "default); \"never\" writes them by simulated time only");
  return o;
}

RunLoop::RunLoop(dem::DemSolver& solver, OutputSettings out, RunParts parts)
    : RunLoop(out, std::move(parts), &solver) {}

RunLoop::RunLoop(OutputSettings out, RunParts parts) : RunLoop(out, std::move(parts), nullptr) {}

RunLoop::RunLoop(OutputSettings out, RunParts parts, dem::DemSolver* dem)
    : dem_(dem), out_(out), parts_(std::move(parts)) {
  if (!dem_ && (!parts_.gas || parts_.gas->coupler()))
    throw std::invalid_argument(
        "RunLoop: a run without particles needs a gas that is not coupled to particles");
  const double dt = this->dt();
  const std::int64_t cycle = parts_.gas ? parts_.gas->cycle() : 1;
  const auto whole_cycles = [&](std::int64_t n) { return (n + cycle - 1) / cycle * cycle; };
  const auto steps = [&](double interval) {
    return whole_cycles(std::max<std::int64_t>(1, std::llround(interval / dt)));
  };
  every_row_ = steps(out_.interval);
  every_snapshot_ = steps(out_.snapshot_interval);
  every_checkpoint_ = out_.checkpoint_interval > 0 && std::isfinite(out_.checkpoint_interval)
                          ? steps(out_.checkpoint_interval)
                          : 0;
  last_step_ = whole_cycles(std::llround(out_.end_time / dt));
  if (dem_ && parts_.watch.on) dem_->set_speed_limit(parts_.watch.max_speed);
}

Instant RunLoop::now() const {
  if (dem_) return {dem_->time(), dem_->steps()};
  return {parts_.gas->time(), parts_.gas->gas().steps()};
}

double RunLoop::dt() const {
  return dem_ ? dem_->settings().dt : parts_.gas->dt();
}

void RunLoop::step_clock() {
  if (dem_)
    dem_->step();
  else
    parts_.gas->step_alone();
}

namespace {
struct SignalHandlers {
  void (*int_)(int) = SIG_DFL;
  void (*term_)(int) = SIG_DFL;
};
SignalHandlers g_old_handlers;

// The sums of the checkpoint just written (run_cost.hpp): the run's cost over all its invocations.
void log_cost(Log& log, const std::string& dir) {
  const auto c = read_run_cost(dir + "/checkpoint.h5");
  if (!c || !(c->to_s > c->from_s)) return;
  const double span = c->to_s - c->from_s;
  log.line("stepping wall time over all invocations since t = " + to_text(c->from_s) +
           " s: " + to_text(c->wall_s) + " s for " + to_text(span) + " simulated s (" +
           to_text(c->wall_s / span) + " s/s)");
}

void restore_signals() {
  std::signal(SIGINT, g_old_handlers.int_);
  std::signal(SIGTERM, g_old_handlers.term_);
}
}  // namespace

void RunLoop::diverged(Progress& progress, const std::string& msg) const {
  progress.finish();
  restore_signals();
  if (log_) log_->line("error: " + msg);
  throw Diverged(msg);
}

std::optional<std::string> RunLoop::observer_health() {
  const Instant t = now();
  for (Observer* o : parts_.observers)
    if (auto msg = o->health(t)) return msg;
  return std::nullopt;
}

void RunLoop::check_health(Progress& progress, double stored0) {
  if (auto msg = observer_health()) diverged(progress, *msg);
  if (auto msg = dem_health(stored0)) diverged(progress, *msg);
  last_sound_time_ = now().time_s;
}

namespace {

// The fix a DEM divergence message offers: the step against the contact time, and the stiffness
// that sets it (choose_time_step's terms: dem.dt is the original particles' step).
std::string dem_fix(const DemWatch& w, double dt, bool speed) {
  const StepChoice& c = w.step;
  const double tc = c.scales.contact_time;
  if (!(tc > 0) || !std::isfinite(tc))
    return "the contact time t_c = " + to_text(tc) + " s for " + c.scales.where +
           " cannot be resolved by any step: check materials.stiffness, youngs_modulus and density "
           "against the material data";
  const std::string ratio = dt >= tc ? to_text(dt / tc, 3) + " t_c" : "t_c/" + to_text(tc / dt, 3);
  std::string s = "the step dt = " + to_text(dt) + " s is " + ratio +
                  " (contact time t_c = " + to_text(tc) + " s for " + c.scales.where +
                  " at dem.impact_speed = " + to_text(c.impact_speed) + " m/s)";
  if (dt > tc / 20) {
    s += ": lower dem.dt to at most t_c/20 = " + to_text(tc / 20 / c.dt_factor) + " s" +
         (c.forced ? " and drop dem.force_dt = true, which let this step pass" : "") +
         ", or soften the contact (a lower materials.youngs_modulus or stiffness lengthens t_c)";
  } else {
    s +=
        ": impacts faster than dem.impact_speed shorten a Hertz contact, so raise dem.impact_speed "
        "to the speeds reached (the default dem.dt follows), and check materials.youngs_modulus "
        "and stiffness against the material data";
    if (speed) s += "; or raise dem.max_speed_factor if particles are expected this fast";
  }
  return s;
}

bool finite(const Vec3& a) {
  return a.allFinite();
}

// "particle id 12 at [x, y, z] m has ..." for particle k's state.
std::string particle_text(std::int64_t id, const Vec3& x, const Vec3& v, const Vec3& omega,
                          const Vec3& f, const Vec3& t, const DemWatch& w) {
  std::string s =
      "particle id " + std::to_string(id) + (finite(x) ? " at " + vec_text(x) + " m" : "");
  std::vector<std::string> bad;
  if (!finite(x)) bad.push_back("position " + vec_text(x) + " m");
  if (!finite(v)) bad.push_back("velocity " + vec_text(v) + " m/s");
  if (!finite(omega)) bad.push_back("angular velocity " + vec_text(omega) + " rad/s");
  if (!finite(f)) bad.push_back("force " + vec_text(f) + " N");
  if (!finite(t)) bad.push_back("torque " + vec_text(t) + " N m");
  if (!bad.empty()) {
    s += " has a non-finite ";
    for (std::size_t k = 0; k < bad.size(); ++k)
      s += (k == 0 ? "" : k + 1 == bad.size() ? " and " : ", ") + bad[k];
    return s;
  }
  return s + " moves at " + to_text(v.norm()) + " m/s, above the watchdog's limit of " +
         to_text(w.max_speed) + " m/s (" + w.speed_basis + "; dem.max_speed_factor) (velocity " +
         vec_text(v) + " m/s, force " + vec_text(f) + " N)";
}

}  // namespace

std::optional<std::string> RunLoop::dem_health(double stored0) const {
  const DemWatch& w = parts_.watch;
  if (!dem_ || !w.on) return std::nullopt;
  const dem::DemSolver& solver = *dem_;
  const auto& p = solver.particles();
  const double dt = solver.settings().dt;
  const std::string at = "DEM diverged at t = " + to_text(solver.time()) + " s (DEM step " +
                         std::to_string(solver.steps()) + "): ";
  const std::string kept = "; the last checkpoint and output are kept; fix: ";
  // The first unsound particle in storage order (the same for any thread count).
  const double limit2 = w.max_speed * w.max_speed;
  std::size_t fastest = 0;
  double top2 = -1;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const double v2 = p.v[k].squaredNorm();
    const bool sound = finite(p.x[k]) && finite(p.v[k]) && finite(p.omega[k]) &&
                       finite(p.force[k]) && finite(p.torque[k]);
    if (!sound || !(v2 <= limit2))
      return at + particle_text(p.id[k], p.x[k], p.v[k], p.omega[k], p.force[k], p.torque[k], w) +
             kept + dem_fix(w, dt, sound);
    if (v2 > top2) top2 = v2, fastest = k;
  }
  // The energy balance against the energy moved: a reference the potential energy's zero does
  // not shift. The floor covers the round-off of the potential energy's sums.
  const dem::EnergyTotals e = solver.energy();
  const double error = e.stored() + e.dissipated() - e.injected(stored0);
  const double moved = e.kinetic() + e.elastic + e.dissipated() + std::abs(e.wall_work) +
                       std::abs(e.external_work) + std::abs(e.stiffness_change) +
                       std::abs(e.inserted) + std::abs(e.removed);
  const double floor = 1e-9 * (std::abs(e.potential) + std::abs(stored0));
  if (std::abs(error) <= w.max_energy_error * moved + floor) return std::nullopt;
  std::string msg = at + "the energy balance error " + to_text(error) + " J is " +
                    to_text(std::abs(error) / moved) + " of the " + to_text(moved) +
                    " J of energy moved (kinetic, elastic, dissipated and sources), above " +
                    "dem.max_energy_error = " + to_text(w.max_energy_error);
  if (top2 >= 0)
    msg += "; the fastest particle, id " + std::to_string(p.id[fastest]) + " at " +
           vec_text(p.x[fastest]) + " m, moves at " + to_text(std::sqrt(top2)) + " m/s";
  return msg + kept + dem_fix(w, dt, false);
}

void RunLoop::dem_alarm(Progress& progress) {
  const dem::DemAlarm& a = *dem_->alarm();
  const DemWatch& w = parts_.watch;
  std::string msg = "DEM diverged at t = " + to_text(a.time) + " s (DEM step " +
                    std::to_string(a.step) + ", after its half kick and drift): " +
                    particle_text(a.id, a.x, a.v, a.omega, a.force, a.torque, w) +
                    "; the last checkpoint and output are kept; fix: " +
                    dem_fix(w, dem_->settings().dt, a.finite);
  // A coupled run names the side that failed first: the DEM is checked at every step, the gas at
  // outputs, so the gas is looked at now as well.
  if (parts_.gas) {
    if (auto gas = observer_health())
      msg += ". The gas, within its limits at t = " + to_text(last_sound_time_) +
             " s (its last check), is outside them now too: " + *gas;
    else
      msg += ". The gas is within its limits";
  }
  diverged(progress, msg);
}

DemWatch dem_watch(const StepChoice& step, const dem::DemSolver& s,
                   const std::vector<ExpectedSpeed>& others) {
  std::vector<ExpectedSpeed> v = {{step.impact_speed, "dem.impact_speed"}};
  const dem::DemSettings& set = s.settings();
  if (const double g = set.gravity.norm(); g > 0) {
    const Vec3 L = set.domain.length();
    const double h = (set.gravity.cwiseAbs() / g).dot(L);  // the domain's extent along gravity
    v.push_back({std::sqrt(2 * g * h), "the free fall across the domain"});
  }
  const auto motion_speed = [](const dem::PrescribedMotion& m, const auto& points) {
    double top = 0;
    for (const Vec3& q : points)
      top = std::max(top, (m.velocity + m.omega * m.axis.cross(q - m.axis_point)).norm());
    return top;
  };
  for (const dem::Wall& w : s.walls()) {
    double top = 0;
    if (const auto* p = std::get_if<dem::PlaneWall>(&w.shape)) top = p->velocity.norm();
    if (const auto* c = std::get_if<dem::CylinderWall>(&w.shape))
      top = std::abs(c->omega) * c->radius;
    if (const auto* m = std::get_if<dem::MeshWall>(&w.shape))
      top = motion_speed(m->motion, m->mesh.vertices);
    if (const auto* b = std::get_if<dem::BoxWall>(&w.shape))
      top = motion_speed(b->motion, b->corners(0));
    if (top > 0) v.push_back({top, "wall " + w.name});
  }
  double fastest = 0;
  for (const Vec3& u : s.particles().v) fastest = std::max(fastest, u.norm());
  if (fastest > 0) v.push_back({fastest, "the fastest particle at the start"});
  ExpectedSpeed limit{0, ""};
  for (const auto& o : others)
    if (!o.limit)
      v.push_back(o);
    else if (o.speed > limit.speed)
      limit = o;
  const auto top = *std::max_element(
      v.begin(), v.end(), [](const auto& a, const auto& b) { return a.speed < b.speed; });
  DemWatch w;
  w.on = true;
  w.step = step;
  w.max_speed = step.max_speed_factor * top.speed;
  w.speed_basis = to_text(step.max_speed_factor) + " x " + to_text(top.speed) + " m/s, " + top.what;
  if (limit.speed > w.max_speed) w.max_speed = limit.speed, w.speed_basis = limit.what;
  w.max_energy_error = step.max_energy_error;
  return w;
}

namespace {
const std::vector<std::string> kColumns = {"time_s",
                                           "particles",
                                           "kinetic_energy_J",
                                           "kinetic_translational_J",
                                           "kinetic_rotational_J",
                                           "potential_energy_J",
                                           "elastic_energy_J",
                                           "dissipated_normal_damping_J",
                                           "dissipated_tangential_damping_J",
                                           "dissipated_sliding_J",
                                           "dissipated_rolling_J",
                                           "stiffness_change_J",
                                           "wall_work_J",
                                           "energy_injected_J",
                                           "energy_balance_error_J",
                                           "contacts_pp",
                                           "contacts_pw",
                                           "collisions_pp",
                                           "collisions_pw",
                                           "collision_rate_pp_per_s",
                                           "collision_rate_pw_per_s",
                                           "mass_removed_kg",
                                           "neighbour_rebuilds"};
}  // namespace

const std::vector<std::string>& loop_columns(bool particles) {
  static const std::vector<std::string> clock_only = {kColumns.front()};
  return particles ? kColumns : clock_only;
}

void RunLoop::write_row(double stored0, bool regular) {
  const Instant t = now();
  std::vector<double> row = {t.time_s};
  if (dem_) {
    const dem::DemSolver& s = *dem_;
    const auto e = s.energy();
    // Collisions begun per second since the previous row.
    const double span = t.time_s - prev_t_;
    const auto rate = [&](std::int64_t now, std::int64_t prev) {
      return span > 0 ? double(now - prev) / span : 0.0;
    };
    const double injected = e.injected(stored0);
    row.insert(row.end(), {double(s.particles().size()),
                           e.kinetic(),
                           e.kinetic_translational,
                           e.kinetic_rotational,
                           e.potential,
                           e.elastic,
                           e.normal_damping,
                           e.tangential_damping,
                           e.sliding,
                           e.rolling,
                           e.stiffness_change,
                           e.wall_work,
                           injected - stored0,
                           e.stored() + e.dissipated() - injected,
                           double(s.contacts_pp()),
                           double(s.contacts_pw()),
                           double(s.collisions().started_pp()),
                           double(s.collisions().started_pw()),
                           rate(s.collisions().started_pp(), prev_pp_),
                           rate(s.collisions().started_pw(), prev_pw_),
                           s.mass_removed(),
                           double(s.rebuilds())});
  }
  for (const Observer* o : parts_.observers) o->on_row(t, row);
  ts_.row(row);
  if (!regular || !dem_) return;  // an end-of-run row does not start a new rate interval (resume)
  prev_t_ = t.time_s;
  prev_pp_ = dem_->collisions().started_pp();
  prev_pw_ = dem_->collisions().started_pw();
}

void RunLoop::write_particles(const std::string& dir) const {
  const auto& p = dem_->particles();
  const int index = static_cast<int>(snapshot_times_.size()) - 1;
  char name[64];
  std::snprintf(name, sizeof name, "snapshots/particles_%06d.h5", index);
  fs::create_directories(dir + "/snapshots");
  {
    H5Out f(dir + "/" + name);
    f.attr("time_s", dem_->time());
    f.write("/position_m", p.x);
    f.write("/velocity_m_per_s", p.v);
    f.write("/angular_velocity_rad_per_s", p.omega);
    f.write("/radius_m", p.radius);
    f.write("/force_N", p.force);
    f.write("/id", p.id);
    f.write("/material", p.material);
    f.write("/coordination_number", dem_->coordination());
    // The XDMF's connectivity (one vertex cell per particle): 0 .. N-1.
    std::vector<std::int32_t> vertex(p.size());
    for (std::size_t k = 0; k < vertex.size(); ++k) vertex[k] = static_cast<std::int32_t>(k);
    f.write("/vertex_index", vertex);
    f.commit();
  }
  // particles.h5 links every snapshot (HDF5 external links), rewritten atomically each time.
  H5Out master(dir + "/particles.h5");
  master.write("/time_s", snapshot_times_);
  master.group("/snapshots");
  for (int k = 0; k <= index; ++k) {
    std::snprintf(name, sizeof name, "snapshots/particles_%06d.h5", k);
    char link[32];
    std::snprintf(link, sizeof link, "/snapshots/%06d", k);
    master.external_link(link, name, "/");
  }
  master.commit();
  write_particles_xdmf(dir, snapshot_times_);
}

void RunLoop::write_snapshot(const std::string& dir) {
  snapshot_times_.push_back(now().time_s);
  // The particles' files first: an observer's snapshot (the gas's) may be read beside them.
  if (dem_) write_particles(dir);
  if (!parts_.observers.empty()) {
    std::vector<SnapshotArray> arrays;
    for (const Observer* o : parts_.observers) {
      auto a = o->snapshot_arrays();
      arrays.insert(arrays.end(), std::make_move_iterator(a.begin()),
                    std::make_move_iterator(a.end()));
    }
    for (Observer* o : parts_.observers) o->on_snapshot(dir, snapshot_times_, arrays);
  }
}

void RunLoop::write_checkpoint(const std::string& dir, double stored0, bool final) const {
  // Two generations: the checkpoint that verifies becomes checkpoint.prev.h5 (a hard link renamed
  // over the older one, so checkpoint.h5 never goes missing) before the new one replaces it.
  const std::string file = dir + "/checkpoint.h5", prev = dir + "/" + kPreviousCheckpoint;
  if (fs::exists(file) && !checkpoint_fault(file)) {
    std::error_code ec;
    fs::remove(prev + ".tmp", ec);
    fs::create_hard_link(file, prev + ".tmp", ec);
    if (ec) fs::copy_file(file, prev + ".tmp", fs::copy_options::overwrite_existing);
    fs::rename(prev + ".tmp", prev);
  }
  write_checkpoint_file(file, stored0, final);
  if (const auto fault = checkpoint_fault(file))
    throw std::runtime_error("the checkpoint just written, " + file + ", does not verify (" +
                             *fault + "); the generation before is kept as " + prev);
  // The manifest with the checkpoint it describes (its cost sums are the checkpoint's).
  RunManifest m;
  m.version = LBDEM_VERSION;
  if (identity_) m.scenario = identity_->scenario, m.config_hash = identity_->hash();
  m.time_s = now().time_s;
  m.end_time_s = out_.end_time;
  m.complete = final;
  if (log_) m.derived = log_->derived_values();
  m.cost = read_run_cost(file);
  write_run_manifest(dir, m);
}

void RunLoop::write_checkpoint_file(const std::string& file, double stored0, bool final) const {
  const double t = now().time_s;
  H5Out f(file);
  f.checksum_datasets();
  f.attr("format", std::string(kCheckpointFormat));
  f.attr("time_s", t);
  f.attr("timeseries_rows", std::int64_t(ts_.rows() - (extra_row_ ? 1 : 0)));
  std::vector<double> snaps = snapshot_times_;
  if (extra_snapshot_ && !snaps.empty()) snaps.pop_back();
  f.write("/snapshot_times_s", snaps);
  if (dem_) {
    f.attr("stored_energy_at_start_J", stored0);
    f.write("/rate_reference", std::vector<double>{prev_t_, double(prev_pp_), double(prev_pw_)});
    dem_->save(f);
  }
  if (identity_)
    save_identity(f, *identity_, dem_ ? std::int64_t(dem_->particles().size()) : 0,
                  final ? out_.end_time : 0.0);
  for (const Observer* o : parts_.observers) o->on_checkpoint(f);
  if (parts_.gas) parts_.gas->save(f);
  cost_.save(f, t);
  f.commit();
}

long RunLoop::resume(const std::string& file, double& stored0) {
  const H5In f(file);
  const long rows = static_cast<long>(f.attr_int("timeseries_rows"));
  snapshot_times_ = f.doubles("/snapshot_times_s");
  if (dem_) {
    stored0 = f.attr_double("stored_energy_at_start_J");
    dem_->load(f);
  }
  for (Observer* o : parts_.observers) o->on_resume(f);
  if (parts_.gas) {
    if (dem_)
      parts_.gas->load(f, *dem_);
    else
      parts_.gas->load_alone(f);
  }
  const Instant t = now();
  cost_.resume(f, t.time_s);
  if (dem_) {
    const auto prev = f.doubles("/rate_reference");
    prev_t_ = prev[0], prev_pp_ = std::int64_t(prev[1]), prev_pw_ = std::int64_t(prev[2]);
  }
  last_sound_time_ = t.time_s;
  log_->line("resumed from " + file + " at t = " + to_text(t.time_s) + " s (step " +
             std::to_string(t.step) + ")");
  return rows;
}

int RunLoop::run(const RunContext& ctx) {
  log_ = ctx.log;
  std::vector<std::string> columns = loop_columns(dem_ != nullptr);
  for (const Observer* o : parts_.observers) {
    const auto c = o->row_columns();
    columns.insert(columns.end(), c.begin(), c.end());
  }
  double stored0 = 0;
  identity_ = ctx.identity;
  if (ctx.resume) {
    // The generation check_resume chose and verified (run_command), if it ran.
    const long rows =
        resume(ctx.checkpoint.empty() ? ctx.dir + "/checkpoint.h5" : ctx.checkpoint, stored0);
    ts_.open(ctx.dir + "/timeseries.csv", columns, rows);
  } else {
    cost_.begin(now().time_s);
    if (dem_) stored0 = dem_->energy().stored();
    ts_.open(ctx.dir + "/timeseries.csv", columns, -1);
    write_row(stored0);
    write_snapshot(ctx.dir);
    write_checkpoint(ctx.dir, stored0);
  }
  // The rate counts particle steps, or lattice cell updates without particles.
  const double cells = dem_ ? 0.0 : double(parts_.gas->gas().grid().cells());
  Progress progress(out_.end_time, dem_ ? "particle-steps" : "cell-updates");
  double work = 0;
  g_stop_signal = 0;
  g_old_handlers.int_ = std::signal(SIGINT, on_stop_signal);
  g_old_handlers.term_ = std::signal(SIGTERM, on_stop_signal);
  // A stop waits for the next cycle boundary (at most cycle - 1 DEM steps): only there do all the
  // solvers stand at one time, as a checkpoint needs (a coupled run's exchange interval).
  const std::int64_t cycle = parts_.gas ? parts_.gas->cycle() : 1;
  Stopwatch since_checkpoint;  // stepping wall time since the last checkpoint
  while (now().step < last_step_) {
    // A stop waits for a cycle boundary, or is taken inside a DEM step's gas work (the gas then
    // stands behind the coming DEM step; its checkpoint carries the rest).
    bool stop = g_stop_signal && now().step % cycle == 0;
    if (!stop) {
      const Instant t = now();
      for (Observer* o : parts_.observers) o->before_step(t);
      if (parts_.gas && dem_) parts_.gas->advance(*dem_, stop_requested);
      stop = g_stop_signal && parts_.gas && dem_ && parts_.gas->behind(*dem_);
    }
    if (stop) {
      extra_row_ = extra_snapshot_ = false;
      check_health(progress, stored0);
      write_checkpoint(ctx.dir, stored0);
      if (dem_) dem_->collisions().write(ctx.dir + "/collisions.h5", dem_->time());
      progress.finish();
      restore_signals();
      log_cost(*ctx.log, ctx.dir);
      throw Interrupted("stopped by signal " + std::to_string(int(g_stop_signal)) +
                        " at t = " + to_text(now().time_s) + " s; checkpoint written");
    }
    step_clock();
    if (dem_ && dem_->alarm()) dem_alarm(progress);
    work += dem_ ? double(dem_->particles().size()) : cells;
    const std::int64_t s = now().step;
    const bool last = s == last_step_;
    // Rows and snapshots written only because the run ends here are not kept by a resume, so that
    // a resumed series equals an uninterrupted one.
    extra_row_ = last && s % every_row_ != 0;
    extra_snapshot_ = last && s % every_snapshot_ != 0;
    const bool row = s % every_row_ == 0 || last, snapshot = s % every_snapshot_ == 0 || last;
    // Checkpoints by simulated time, and one after checkpoint_wall_interval of wall time at a
    // cycle boundary (a checkpoint at any boundary resumes bitwise, as a signal stop's does).
    const bool wall_due =
        s % cycle == 0 && since_checkpoint.seconds() >= out_.checkpoint_wall_interval;
    const bool checkpoint =
        (every_checkpoint_ > 0 && s % every_checkpoint_ == 0) || last || wall_due;
    PhaseLap lap;
    if (row || snapshot || checkpoint) check_health(progress, stored0);
    if (row) write_row(stored0, !extra_row_);
    if (snapshot) write_snapshot(ctx.dir);
    if (checkpoint) {
      write_checkpoint(ctx.dir, stored0, last);
      if (dem_) dem_->collisions().write(ctx.dir + "/collisions.h5", dem_->time());
      since_checkpoint.reset();
    }
    lap.to(Phase::output);
    progress.update(now().time_s, work);
  }
  restore_signals();
  progress.update(now().time_s, work, true);
  progress.finish();
  const Instant end = now();
  if (dem_) {
    const auto e = dem_->energy();
    const double injected = e.injected(stored0);
    ctx.log->line("finished at t = " + to_text(end.time_s) + " s after " +
                  std::to_string(end.step) + " steps; energy balance error " +
                  to_text(e.stored() + e.dissipated() - injected) + " J of " +
                  to_text(injected - e.stored()) + " J dissipated or stored away");
  } else {
    ctx.log->line("finished at t = " + to_text(end.time_s) + " s after " +
                  std::to_string(end.step) + " gas steps");
  }
  log_cost(*ctx.log, ctx.dir);
  return 0;
}

void dem_banner(Log& log, const dem::DemSolver& s, double v, double tc, double tr,
                const std::string& where, double feed_r_min, double feed_r_max,
                const DemWatch* watch) {
  const auto& p = s.particles();
  double mass = 0, rmin = 1e300, rmax = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    mass += p.mass[k], rmin = std::min(rmin, p.radius[k]), rmax = std::max(rmax, p.radius[k]);
  if (feed_r_min > 0) rmin = std::min(rmin, feed_r_min), rmax = std::max(rmax, feed_r_max);
  const double dt = s.settings().dt;
  log.line("DEM derived numbers:");
  log.derived("particles", double(p.size()), "");
  log.derived("total particle mass", mass, "kg");
  log.derived("radius min / max", rmin, "m",
              "max " + to_text(rmax) + " m" + (feed_r_min > 0 ? " (with the feed's)" : ""));
  log.derived("characteristic impact speed", v, "m/s");
  log.derived("contact time t_c", tc, "s", "(" + where + ")");
  log.derived("time step dt", dt, "s");
  log.derived("dt / t_c", dt / tc, "", "(steps per contact " + to_text(tc / dt) + ")");
  log.derived("Rayleigh time", tr, "s", "(dt / T_R = " + to_text(dt / tr) + ")");
  log.derived("neighbour skin", s.settings().skin, "m",
              "(" + to_text(s.settings().skin / (2 * rmin)) + " d_min)");
  log.derived("interaction range beyond touch", s.interaction_range(), "m");
  log.derived("walls", double(s.walls().size()), "");
  if (watch && watch->on) {
    log.derived("watchdog: particle speed limit", watch->max_speed, "m/s",
                "(" + watch->speed_basis + ")");
    log.derived("watchdog: energy-balance error limit", watch->max_energy_error, "",
                "(of the energy moved)");
  }
}

}  // namespace lbdem::run

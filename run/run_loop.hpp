#pragma once
// The time loop of every run: it steps the DEM and, with one, the gas (coupled_gas.hpp), or, in a
// run without particles, the gas alone, whose steps are then the clock; and writes timeseries.csv,
// particle snapshots (particles.h5 + .xdmf), collisions.h5, periodic checkpoints and --resume,
// progress and the start-up banner. Output and checkpoint instants are step counts, so a resumed
// run writes at the same steps as one that never stopped. A scenario takes part through its
// observers (observer.hpp): columns, work before each step, its own state in the checkpoint,
// snapshots beside the particles', and a health check.
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "core/time_series.hpp"
#include "dem/dem_solver.hpp"
#include "run/step_choice.hpp"
#include "run/coupled_gas.hpp"
#include "run/observer.hpp"
#include "run/run_context.hpp"
#include "run/run_cost.hpp"

namespace lbdem {
class Progress;
}

namespace lbdem::run {

/// Thrown when SIGINT/SIGTERM stopped the loop after writing a checkpoint.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// SIGINT or SIGTERM arrived during RunLoop::run: work that holds many steps inside one DEM
/// step (the gas of an exchange interval) returns early, between its steps (CoupledGas::advance
/// takes this as its stop test), so that a stop waits at most about one such step.
bool stop_requested();

/// Thrown when an observer's health check or the DEM watchdog found a diverged state; nothing of
/// that state was written (the last output and checkpoint stay). lbdem-cli exits with
/// kDivergedExit.
struct Diverged : std::runtime_error {
  using std::runtime_error::runtime_error;
};
inline constexpr int kDivergedExit = 3;

/// The generation before checkpoint.h5 in a run folder (RunLoop keeps two; a resume takes the
/// newest that verifies).
inline constexpr const char* kPreviousCheckpoint = "checkpoint.prev.h5";

struct OutputSettings {
  double end_time = 1;             // [s]
  double interval = 1e-2;          // timeseries.csv row interval [s]
  double snapshot_interval = 0.1;  // particle snapshot interval [s]
  // [s], > 0; infinite for "never" (then only at the start, the end and a signal stop)
  double checkpoint_interval = 0;
  // [s] of stepping wall time (suspensions left out) after which a checkpoint is written at the
  // next cycle boundary whatever the simulated interval, so a run killed outright loses at most
  // this much work; infinite for "never" or when checkpoint_interval is "never".
  double checkpoint_wall_interval = 900;
  static OutputSettings from(const Config& run, const Config& out);
};

/// The DEM watchdog (docs/user-guide.md, Troubleshooting): a particle whose position, velocity,
/// angular velocity, force or torque is not finite, or that is faster than max_speed, stops the run
/// at the step that finds it (DemSolver::alarm, checked every step); an energy-balance error above
/// max_energy_error times the energy moved (the kinetic, elastic and dissipated energy and every
/// source's magnitude: the potential energy's reference cancels) stops it at an output. The state
/// is then not written: the last checkpoint and output stay.
struct DemWatch {
  bool on = false;
  double max_speed = std::numeric_limits<double>::infinity();  // [m/s]
  std::string speed_basis;  // how max_speed was set, for the banner and the message
  double max_energy_error = 0.1;
  StepChoice step{};  // t_c, where, dt_factor, force_dt: the fix a message offers
};

/// A speed the scenario expects particles to reach [m/s], and where it comes from; a `limit` is
/// already a bound (the gas's watchdog speed) and is not multiplied.
struct ExpectedSpeed {
  double speed;
  std::string what;
  bool limit = false;
};

/// The watchdog of a scenario: max_speed = dem.max_speed_factor x the largest of dem.impact_speed,
/// the free fall across the domain along gravity, the fastest moving wall's surface, the fastest
/// particle now, and `others` (an inflow's speed), or the largest limit in `others` if higher.
DemWatch dem_watch(const StepChoice& step, const dem::DemSolver& s,
                   const std::vector<ExpectedSpeed>& others = {});

/// What a run is made of besides the DEM: the scenario's observers, the gas, the DEM watchdog.
struct RunParts {
  /// Called in this order at each point of the loop (observer.hpp); not owned.
  std::vector<Observer*> observers;
  /// The gas of a run with one (null without): the loop advances it after the observers'
  /// before_step, by the steps that come before each DEM step or, coupled, by the exchange interval
  /// that starts there (coupled_gas.hpp); keeps its output, checkpoint and end instants on whole
  /// coupling cycles, where gas and DEM stand at the same time; and saves and loads it with every
  /// checkpoint. A stop is taken between gas steps (stop_requested): the loop then checkpoints the
  /// gas part-way.
  CoupledGas* gas = nullptr;
  /// The DEM's own watchdog (off unless the scenario sets it: dem_watch).
  DemWatch watch;
};

class RunLoop {
 public:
  RunLoop(dem::DemSolver& solver, OutputSettings out, RunParts parts = {});
  /// A run without particles: the gas (parts.gas) keeps the clock, one step per gas step; no
  /// particle snapshots, collisions.h5 or DEM columns. std::invalid_argument if parts.gas is null
  /// or coupled.
  RunLoop(OutputSettings out, RunParts parts);
  /// Runs to end_time (from the checkpoint if ctx.resume). Returns 0.
  int run(const RunContext& ctx);

 private:
  /// The clock: the DEM's, or the gas's in a run without particles.
  Instant now() const;
  double dt() const;
  void step_clock();

  RunLoop(OutputSettings out, RunParts parts, dem::DemSolver* dem);
  void write_row(double stored0, bool regular = true);
  /// Records the snapshot instant; writes the particles' snapshot (with particles) and calls the
  /// observers' on_snapshot.
  void write_snapshot(const std::string& dir);
  /// snapshots/particles_N.h5, particles.h5 linking them all, and particles.xdmf.
  void write_particles(const std::string& dir) const;
  /// Loads the state of checkpoint `file` (the solvers', the observers', the snapshots' times);
  /// returns the timeseries.csv rows it covers.
  long resume(const std::string& file, double& stored0);
  /// Keeps the current checkpoint as the previous generation, writes the new one and verifies
  /// it (reopened: format, every dataset against its checksum: checkpoint_check.hpp). `final`:
  /// written at run.end_time, which a resume of the finished run then recognises.
  void write_checkpoint(const std::string& dir, double stored0, bool final = false) const;
  void write_checkpoint_file(const std::string& file, double stored0, bool final) const;
  /// Throws Diverged (after restoring the signal handlers) if an observer's health check (the
  /// gas's) or the DEM watchdog objects; the observers are asked first, the DEM having been
  /// checked at every step.
  void check_health(Progress& progress, double stored0);
  /// The first observer's health message, or nullopt if every observer finds its state sound.
  std::optional<std::string> observer_health();
  /// The DEM watchdog on the current state (every particle, and the energy balance): the message,
  /// or nullopt if sound.
  std::optional<std::string> dem_health(double stored0) const;
  /// Stops the run for DemSolver::alarm, naming the observers' (the gas's) health too.
  [[noreturn]] void dem_alarm(Progress& progress);
  [[noreturn]] void diverged(Progress& progress, const std::string& msg) const;

  dem::DemSolver* dem_ = nullptr;  // null in a run without particles
  OutputSettings out_;
  RunParts parts_;
  std::int64_t every_row_ = 1, every_snapshot_ = 1, every_checkpoint_ = 0, last_step_ = 0;
  std::vector<double> snapshot_times_;
  bool extra_row_ = false, extra_snapshot_ = false;
  double prev_t_ = 0;
  std::int64_t prev_pp_ = 0, prev_pw_ = 0;
  double last_sound_time_ = 0;  // the last output instant that passed every check [s]
  TimeSeries ts_;
  Log* log_ = nullptr;
  const RunIdentity* identity_ = nullptr;
  RunCostMeter cost_;
};

/// The loop's own timeseries.csv columns, which every scenario's columns begin with (a scenario
/// adds its observers' row_columns after them): time_s and, with particles, the DEM's.
const std::vector<std::string>& loop_columns(bool particles = true);

/// Derived DEM numbers for the start-up banner. The radius range counts a feed's
/// radii (feed_r_min > 0) with the particles present at the start; `watch` adds the watchdog's
/// limits.
void dem_banner(Log& log, const dem::DemSolver& s, double impact_speed, double contact_time,
                double rayleigh_time, const std::string& where, double feed_r_min = 0,
                double feed_r_max = 0, const DemWatch* watch = nullptr);

}  // namespace lbdem::run

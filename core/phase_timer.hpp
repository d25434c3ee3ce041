#pragma once
// Where a run's wall time goes: one process-wide table of seconds per phase of the
// solvers' steps, which the solvers book with laps (after LAMMPS's Timer, which its styles share),
// and the run command prints at the end of log.txt. A lap reads the run clock (run_clock.hpp) once
// per phase boundary (a few tens of ns, against microseconds and more per phase); switched off
// (run.phase_timers = false) it only tests a flag. Laps are taken outside OpenMP regions, by the
// thread that steps the solvers.
#include <array>
#include <chrono>
#include <string>

#include "core/run_clock.hpp"

namespace lbdem {

enum class Phase : int {
  lbm_collide_stream,           // the fused stream-collide sweep
  lbm_boundaries,               // link rebuilds, outlet sampling, bounce-back / wall function,
                                // mass sources
  dem_integration,              // half kick and drift
  dem_neighbour_search,         // rebuilds: binning, sort, pair list
  dem_pair_contacts,            // particle-particle forces
  dem_walls_and_kick,           // particle-wall forces, force sums and the second half kick
  dem_bookkeeping,              // contact events, wall loads, external work
  coupling_porosity,            // locating particles and mapping their volume to cells
  coupling_interpolation_drag,  // gas fields at the particles, drag, the gas's source terms
  output,                       // health check, time series, snapshots, checkpoints
  count
};

const char* phase_name(Phase p);

class PhaseTimer {
 public:
  static PhaseTimer& global();
  void reset() { seconds_.fill(0.0); }
  void enable(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }
  void add(Phase p, double s) { seconds_[std::size_t(p)] += s; }
  double seconds(Phase p) const { return seconds_[std::size_t(p)]; }
  double total() const;
  /// Lines "  phase  seconds  share of wall" for every phase with time, and the rest of `wall`.
  std::string table(double wall) const;

 private:
  std::array<double, std::size_t(Phase::count)> seconds_{};
  bool enabled_ = true;
};

/// Books the time since its construction, or since its last to(), to a phase.
class PhaseLap {
 public:
  PhaseLap() : on_(PhaseTimer::global().enabled()) {
    if (on_) last_ = clock::now();
  }
  void to(Phase p) {
    if (!on_) return;
    const auto now = clock::now();
    PhaseTimer::global().add(p, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  using clock = RunClock;  // suspensions (SIGTSTP) left out
  bool on_;
  clock::time_point last_{};
};

}  // namespace lbdem

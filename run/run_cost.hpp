#pragma once
// What a run cost, kept in its checkpoint so that the sums survive a run killed without warning
// (the studies report wall time per simulated second of each coarse-graining case). Paper-scale
// cases run for hours and are stopped and resumed from checkpoints; a process killed outright
// (SIGKILL, a lost machine) then neither finishes its log nor returns to the study, so sums kept by
// the caller would lose every such invocation. Here the stepping loop's wall seconds and the phase
// timers' seconds are summed over the invocations and written with each checkpoint (/timing): the
// steps a killed invocation made after its last checkpoint are simulated again on resume, and so
// are counted once, as in a run that never stopped. Not counted: set-up, banner and plots (outside
// the loop), and the output time of the step that writes a checkpoint (booked after it is saved; at
// a step's end that is the health check, row, snapshot and the checkpoint itself: seconds against
// the hours of a paper-scale run). Phases stored under a name this lbdem does not know are dropped
// (their seconds stay in the wall time).
#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/phase_timer.hpp"
#include "core/run_clock.hpp"

namespace lbdem {
class H5In;
class H5Out;
}  // namespace lbdem

namespace lbdem::run {

/// The sums a checkpoint holds.
struct RunCost {
  double from_s = 0;  // simulated time where the sums begin: 0, or a checkpoint written before
                      // they were kept (an older lbdem)
  double to_s = 0;    // the checkpoint's simulated time
  double wall_s = 0;  // wall seconds of the stepping loops (set-up, banner and plots left out)
  std::vector<std::pair<std::string, double>> phases;  // phase timer seconds, by phase_name()
};

/// The sums of the run in progress (RunLoop). The phase timers must have been reset when this
/// invocation began (run_scenario does).
class RunCostMeter {
 public:
  /// A new run, at simulated time t.
  void begin(double t);
  /// A resumed run, from the checkpoint `f` at simulated time t; a checkpoint without sums starts
  /// them at t.
  void resume(const H5In& f, double t);
  /// Writes the sums up to now, the state being at simulated time t.
  void save(H5Out& f, double t) const;

 private:
  using clock = RunClock;  // suspensions (SIGTSTP) left out
  double from_s_ = 0, wall0_ = 0;
  std::array<double, std::size_t(Phase::count)> phase0_{};
  clock::time_point t0_{};
};

/// The sums in an open checkpoint; nullopt if it has none (or their names and seconds disagree);
/// throws (H5 error) if /timing lacks one of its attributes.
std::optional<RunCost> read_run_cost(const H5In& f);
/// The same from a checkpoint's path; nullopt also if the file cannot be read.
std::optional<RunCost> read_run_cost(const std::string& checkpoint);

}  // namespace lbdem::run

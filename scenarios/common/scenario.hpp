#pragma once
// What the run command needs from a scenario: a banner, the loop, and the output settings. A
// scenario is built from a config (and validates all of it in its constructor, before any output);
// it composes solvers and is not a subclass of them.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/log.hpp"
#include "run/run_loop.hpp"
#include "run/run_context.hpp"

namespace lbdem::scenarios {

// The scenarios run on the run layer's loop, clock and run-folder files (run/).
using namespace lbdem::run;

class Scenario {
 public:
  virtual ~Scenario() = default;
  virtual void banner(Log& log) const = 0;
  virtual int run(const RunContext& ctx) = 0;
  virtual const OutputSettings& output() const = 0;
  /// The gas lattice's interior cells per axis (zeros without gas): recorded in each checkpoint,
  /// which a resume must match (checkpoint_check.hpp).
  virtual std::array<std::int64_t, 3> lattice() const { return {0, 0, 0}; }
  /// The columns of the run's timeseries.csv, in order (SI names): the run loop's, then the
  /// scenario's own. Known before the run, so that a study can check the names it will read.
  virtual std::vector<std::string> columns() const = 0;
};

}  // namespace lbdem::scenarios

#pragma once
// How a scenario takes part in a run it does not step itself: the loop (run_loop.hpp) owns the
// clock, the DEM, the gas and every output instant, and calls its observers, in the order given, at
// fixed points of each step. An observer adds timeseries columns, does its work before each step
// (a feed, an outlet, steering), keeps the state a resume needs in the checkpoint, writes beside
// each snapshot and can stop a run whose state has gone bad. The loop hands it only the clock: an
// observer holds the solvers it looks at. Everything has a default that does nothing, so an
// observer overrides only what it adds.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/h5.hpp"

namespace lbdem::run {

/// Where the run's clock stands: the DEM's time and step count, or, in a run without particles,
/// the gas's.
struct Instant {
  double time_s = 0;
  std::int64_t step = 0;
};

/// A one-dimensional data set an observer adds to each gas snapshot (SI, its unit in the name).
struct SnapshotArray {
  std::string name;
  std::vector<double> values;
};

class Observer {
 public:
  virtual ~Observer() = default;

  /// The columns this observer adds to timeseries.csv (SI names), after the loop's own and those
  /// of the observers before it.
  virtual std::vector<std::string> row_columns() const { return {}; }
  /// Appends one value per row_columns() entry to a timeseries row.
  virtual void on_row(const Instant& /*now*/, std::vector<double>& /*row*/) const {}

  /// Before every step of the clock (ahead of the gas's steps for a DEM step): insertion, removal,
  /// steering.
  virtual void before_step(const Instant& /*now*/) {}

  /// The state a resume needs beyond the solvers' (a random generator, a feed's ledger).
  virtual void on_checkpoint(H5Out& /*f*/) const {}
  virtual void on_resume(const H5In& /*f*/) {}

  /// Data sets for the snapshot of a gas (written by the observer that owns the gas).
  virtual std::vector<SnapshotArray> snapshot_arrays() const { return {}; }
  /// After each particle snapshot, with every snapshot time so far (the last one is now) and the
  /// data sets all observers add to a gas snapshot.
  virtual void on_snapshot(const std::string& /*dir*/, const std::vector<double>& /*times*/,
                           const std::vector<SnapshotArray>& /*gas_arrays*/) {}

  /// Called before anything is written at a step (row, snapshot, checkpoint, signal stop): a
  /// message stops the run as diverged, keeping the last good output.
  virtual std::optional<std::string> health(const Instant& /*now*/) { return std::nullopt; }
};

}  // namespace lbdem::run

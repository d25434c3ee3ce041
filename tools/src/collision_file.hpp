#pragma once
// Reader of a run's collisions.h5 (written by dem/collision_stats.cpp): the impact-speed
// histograms, totals and spatial grid, all cumulative from t = 0 to the file's time_s, and the
// opt-in per-contact rows, kept for contacts ending in [rows_start, rows_end] up to a row budget.
#include "tools/src/collision_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lbdem::tools {

struct CollisionRows {
  std::vector<double> t_start, t_end;  // [s]
  std::vector<std::int64_t> id_j;      // < 0: a wall
  std::vector<double> vn, vt;          // impact normal / tangential speed [m/s]
  std::vector<double> dissipated;      // [J]
  std::size_t size() const { return t_start.size(); }
};

struct CollisionFile {
  double time = 0;                // time_s of the totals, histograms and grid [s]
  std::int64_t rows_dropped = 0;  // rows not kept because the budget was full
  Histogram vn[2], vt[2];         // [0]: particle–particle, [1]: particle–wall
  bool has_rows = false;
  CollisionRows rows;
  bool has_grid = false;
  std::size_t nz = 0, ny = 0, nx = 0;           // grid shape, x fastest
  std::vector<double> grid_dissipated;          // [J] per cell
  std::vector<double> grid_counts;              // contacts ended per cell
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // grid box [m]
};

/// Reads RUN_DIR/collisions.h5; ToolError if it is missing.
CollisionFile read_collisions(const std::string& run_dir);

/// Interval of contact start times over which the rows hold every contact: from rows_start to the
/// last kept end time when the budget ran out, else to min(rows_end, time). Rows are selected by
/// end time; a contact lasts a few contact times t_c ≪ any useful window, so the edge is ignored.
struct Coverage {
  double from = 0, to = -1;
  /// Slack of 1e-8 relative: timeseries.csv holds times to 10 significant digits, the HDF5 file
  /// to 17, so the same end time can differ in the 10th digit.
  bool covers(double a, double b) const {
    const double slack = 1e-8 * std::max(std::abs(a), std::abs(b));
    return from <= a + slack && b <= to + slack;
  }
};
Coverage rows_coverage(const CollisionFile& f, double rows_start, double rows_end);

}  // namespace lbdem::tools

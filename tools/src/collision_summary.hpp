#pragma once
// Collision frequency, impact speeds and dissipated energy of a run folder over a time window
// (what lbdem-collision-stats prints, and the jet-mill study compares): frequencies and energies
// from timeseries.csv, differenced across the window; impact speeds from collisions.h5 (its rows
// where they cover the window, else its whole-run histograms); the spatial dissipation summary.
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "tools/src/collision_metrics.hpp"
#include "tools/src/run_folder.hpp"

namespace lbdem::tools {

struct CollisionSummary {
  std::vector<std::pair<std::string, std::string>> fields;  // one CSV row, in column order
  Histogram vn[2], vt[2];                                   // impact speeds: pp, pw
  std::string label, source;                                // where the impact speeds came from
  void add(const std::string& name, double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    fields.emplace_back(name, buf);
  }
  /// The field `name` as a number; NaN if absent.
  double get(const std::string& name) const {
    for (const auto& [k, v] : fields)
      if (k == name) return std::strtod(v.c_str(), nullptr);
    return std::numeric_limits<double>::quiet_NaN();
  }
};

/// The window's figures of `run`; ToolError if [from, to] holds fewer than two rows.
CollisionSummary analyse_collisions(const RunFolder& run, const std::string& label, double from,
                                    double to);
/// The printed table, one line per run.
std::string collision_table(const std::vector<CollisionSummary>& res);
/// PATH (one row per run) and PATH-stem_impact_speed.csv (the histograms), each atomically.
void write_collision_csvs(const std::string& path, const std::vector<CollisionSummary>& res);

}  // namespace lbdem::tools

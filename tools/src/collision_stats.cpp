// lbdem-collision-stats: collision frequency, impact speeds, dissipated energy and the spatial
// dissipation summary of one or more run folders (a coarse-graining series) over a time window
// (tools/src/collision_summary.hpp).
#include "tools/src/collision_summary.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace lbdem::tools;

namespace {

struct Options {
  std::vector<std::string> dirs, labels;
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
  std::string csv;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "lbdem-collision-stats: collision frequency, impact speeds and dissipated energy of run "
      "folders over a time window.\n"
      "Frequencies and energies come from timeseries.csv (cumulative collisions_pp/_pw and "
      "dissipated_*_J, differenced between the first and last row inside [--from, --to]). Per "
      "parcel: 2 n_pp / (N dt) and n_pw / (N dt) (a particle-particle collision involves two "
      "parcels); per represented original particle: per parcel / l^3, l = [coarse_grain] "
      "size_factor of config.toml (1 if absent). Impact speeds come from collisions.h5 /rows "
      "when they hold every contact of the window (set output.collisions.rows_start/rows_end "
      "around it), else from its /histograms, which, like /grid (the spatial map), cover the "
      "whole run. The powder mass for J/kg is that of the latest snapshot up to the window end. "
      "Rows miss the contacts still open at the end of the run. A folder without collisions.h5 "
      "(a run's kept small outputs) still gives the counts, frequencies and energies; its impact "
      "speeds and grid are NaN. Without particles.h5 the mass is timeseries.csv's "
      "mass_inserted_kg - mass_removed_kg for a run that began with no particles, else NaN.\n"
      "Writes --csv OUT.csv (one row per run) and OUT_impact_speed.csv; plot them with "
      "/usr/bin/python3 tools/collision_stats.py OUT.csv"};
  Options o;
  app.add_option("RUN_DIR", o.dirs, "run folders, e.g. a CG series")->required();
  app.add_option("--from", o.from, "window start [s] (default: first row)");
  app.add_option("--to", o.to,
                 "window end [s], inclusive (default: last row; a run writes its last row up to "
                 "an exchange cycle past its end time, so a window ending there needs a pad)");
  app.add_option("--csv", o.csv, "write the table to this CSV and OUT_impact_speed.csv");
  app.add_option("--label", o.labels, "label per run, in order (default: \"l = <size_factor>\")")
      ->allow_extra_args(false);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "lbdem-collision-stats: %s (see --help)\n", e.what());
    return kToolErrorExit;
  }
  return guarded_main("lbdem-collision-stats", [&] {
    check_window_and_labels(o.from, o.to, o.labels.size(), o.dirs.size());
    std::vector<CollisionSummary> res;
    for (std::size_t k = 0; k < o.dirs.size(); ++k) {
      const RunFolder run = RunFolder::open(o.dirs[k]);
      res.push_back(analyse_collisions(run, run_label(o.labels, k, run.size_factor), o.from, o.to));
    }
    std::fputs(collision_table(res).c_str(), stdout);
    if (!o.csv.empty()) {
      write_collision_csvs(o.csv, res);
      const std::string stem =
          o.csv.size() > 4 && o.csv.ends_with(".csv") ? o.csv.substr(0, o.csv.size() - 4) : o.csv;
      std::printf("wrote %s and %s_impact_speed.csv\n", o.csv.c_str(), stem.c_str());
    }
    return 0;
  });
}

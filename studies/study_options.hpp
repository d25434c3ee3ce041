#pragma once
// Options of `./lbdem study NAME`.
#include <cmath>
#include <string>
#include <vector>

namespace lbdem::studies {

struct StudyOptions {
  std::string name, out;
  std::vector<std::string> cases;  // empty: all of the study's cases
  std::vector<std::string> sets;   // --set overrides applied to every case
  double end_time = 0;             // > 0: overrides each case's run.end_time (a measured window)
  int threads = 0;
  bool list = false, no_plots = false;
  bool quick = false;   // the study's short check form (studies that have one)
  bool no_run = false;  // compare the cases already in the folder; run and resume none
  double window_from = 0, window_to = 0;  // > 0: the statistics window [s] (fluidized_bed, cg)
  // The cg study: the user's config, its size factors, the timeseries columns compared, the
  // scaling rule of every level (empty: the config's) and the relative difference called close.
  std::string config, rule;
  std::vector<double> levels;
  std::vector<std::string> level_sets;  // "L:key=value": an override for the level l = L only
  std::vector<std::string> observables;
  double tolerance = std::nan("");  // NaN: not given (the cg study takes 0.05)
};

}  // namespace lbdem::studies

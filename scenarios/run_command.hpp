#pragma once
// The `run` and `study` verbs: scenario table, run folder life cycle, resume, plots.
#include <string>
#include <vector>

#include "scenarios/study_options.hpp"

namespace lbdem::scenarios {

struct RunOptions {
  std::string scenario, config, out, resume;
  std::vector<std::string> sets;
  int threads = 0;
  bool list = false, no_plots = false;
};

/// Validates the whole input before anything is written (InputError -> exit 2, no run folder), then
/// creates the run folder, writes config.toml and log.txt, runs, and makes the plots.
int run_scenario(const RunOptions& opt);
/// Runs the named study's cases one after another (see each study's header).
int run_study(const StudyOptions& opt);

}  // namespace lbdem::scenarios

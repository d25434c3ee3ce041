#pragma once
// The `run` verb: scenario table, run folder life cycle, resume, plots.
#include <string>
#include <vector>

#include "core/config.hpp"

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

/// The scenarios' names, as `run --list` gives them.
std::vector<std::string> scenario_names();
/// Reads `cfg` as the run command would for scenario `name` (builds the scenario and discards
/// it, then checks for unknown keys); InputError as for a run. Returns the run's timeseries.csv
/// columns (Scenario::columns).
std::vector<std::string> read_as_scenario(const std::string& name, const Config& cfg);
/// The `config` verb: prints the generated key reference (scenarios/config_reference.hpp).
int print_config_reference();

}  // namespace lbdem::scenarios

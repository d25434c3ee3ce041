#pragma once
// What every `./lbdem study` does per case: run it into ROOT/NAME from its preset, or resume it if
// it stopped (or if --end-time asks for more), and keep the wall and simulated time summed over the
// invocations that advanced it (study_timing.txt), so a table can give wall time per simulated
// second however often the case was resumed.
#include <string>
#include <utility>
#include <vector>

#include "scenarios/study_options.hpp"

namespace lbdem::scenarios {

struct StudyCase {
  std::string name, scenario, preset;  // preset: path of the TOML file
  std::vector<std::string> sets;       // --set overrides of the case
};

/// Runs or resumes one case (nothing if it is finished and long enough). Returns the run's exit
/// code (0 if nothing was to do).
int run_study_case(const std::string& root, const StudyCase& c, const StudyOptions& opt,
                   const std::string& banner);

/// Every name of --cases is one of `known`, else InputError naming the nearest known case.
void check_case_names(const std::vector<std::string>& wanted, const std::vector<std::string>& known,
                      const std::string& study);

/// The last time_s of a run's timeseries.csv, 0 if none.
double last_time(const std::string& csv);
/// Summed wall and simulated seconds of a case (study_timing.txt; zeros if absent).
std::pair<double, double> read_timing(const std::string& dir);

}  // namespace lbdem::scenarios

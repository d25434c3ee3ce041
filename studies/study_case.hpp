#pragma once
// What every `./lbdem study` does per case: run it into ROOT/NAME from its preset, or resume it if
// it stopped (or if --end-time asks for more), and keep the wall and simulated time summed over the
// invocations that advanced it (study_timing.txt), so a table can give wall time per simulated
// second however often the case was resumed. Those sums come from the run's checkpoint
// (run_cost.hpp), which also counts invocations killed without warning; cases run before it kept
// them were summed here, over the invocations that returned.
#include <string>
#include <utility>
#include <vector>

#include "studies/study_options.hpp"

namespace lbdem::studies {

struct StudyCase {
  std::string name, scenario, preset;  // preset: path of the TOML file
  std::vector<std::string> sets;       // --set overrides of the case
};

/// A number for a study table, printf-formatted (default 4 significant digits); empty where it is
/// not finite (a figure a case does not have yet).
std::string fmt(double v, const char* format = "%.4g");

/// A shell word for a study's std::system calls: single quotes, each ' inside written as '\''.
std::string shell_quoted(const std::string& s);

/// Runs or resumes one case (nothing if it is finished and long enough). Returns the run's exit
/// code (0 if nothing was to do).
int run_study_case(const std::string& root, const StudyCase& c, const StudyOptions& opt,
                   const std::string& banner);

/// Every name of --cases is one of `known`, else InputError naming the nearest known case.
void check_case_names(const std::vector<std::string>& wanted, const std::vector<std::string>& known,
                      const std::string& study);

/// The cases an invocation runs, as indices into `known`: those --cases names, in the order given
/// (a name given twice runs once), so that a user decides which case runs first; without
/// --cases, those for which `by_default` holds, in the study's order. Names must have passed
/// check_case_names.
std::vector<std::size_t> cases_to_run(const std::vector<std::string>& wanted,
                                      const std::vector<std::string>& known,
                                      const std::vector<bool>& by_default);

/// The last time_s of a run's timeseries.csv, 0 if none.
double last_time(const std::string& csv);
/// Summed wall and simulated seconds of a case (study_timing.txt; zeros if absent).
std::pair<double, double> read_timing(const std::string& dir);
/// Summed phase seconds of a case (study_phases.txt, "seconds<TAB>phase" per line): (phase,
/// seconds) in the file's order; a malformed line is skipped; empty if absent.
std::vector<std::pair<std::string, double>> read_phase_sums(const std::string& dir);
/// The simulated time where those sums begin, if they are the run's own (run_cost.hpp: the
/// stepping loop's wall time, from the first checkpoint that kept sums; 0 for a run timed from its
/// start); NaN if the study summed them (two numbers in study_timing.txt: whole invocations, set-up
/// and plots included, the killed ones left out) or if there is no timing.
double timed_from(const std::string& dir);

/// The phase table a run writes at the end of its log.txt ("wall time by phase"), the last one at
/// or after byte `from`: (phase, seconds) in the log's order; empty if there is none.
std::vector<std::pair<std::string, double>> read_phase_table(const std::string& log,
                                                             std::streamoff from = 0);

/// Wall seconds per simulated second of a case, whole and split by part (which part
/// bounds the coarse-graining speed-up). The parts are the phase timers' groups, summed over the
/// study's invocations (study_phases.txt); a case run before those sums were kept takes its last
/// invocation's shares of the summed wall time (`from_shares`). total 0: no timing yet.
struct PartCosts {
  double total = 0, gas = 0, dem = 0, coupling = 0, rest = 0;
  bool split = false, from_shares = false;
};
PartCosts part_costs(const std::string& dir);

/// The coarse-graining speed-up columns of a study table (kSpeedupColumns, in that order) for the
/// case in `dir` against the reference case in `ref_dir` (empty or without timing: the speed-ups
/// are left blank): the case's wall seconds per simulated second for the gas, the DEM and the
/// exchange; the measured speed-up, whole and of the DEM and gas parts, beside the part's ideal
/// from the banners (DEM: parcels_ref / parcels x dt / dt_ref, which is l^4 when the step grows
/// with l; gas: cells_ref / cells x its step over the reference's); and the part that takes most
/// of the case's time, which bounds the speed-up.
inline constexpr const char* kSpeedupColumns =
    "gas_s_per_simulated_s,dem_s_per_simulated_s,coupling_s_per_simulated_s,speedup,"
    "dem_speedup,dem_ideal_speedup,gas_speedup,gas_ideal_speedup,bounded_by,timed_from_s";
/// parcels, parcels_ref: the parcel counts where the banner's start count is not the run's (a
/// feed); 0: the banners' "particles".
std::string speedup_columns(const std::string& dir, const std::string& ref_dir, double parcels = 0,
                            double parcels_ref = 0);

/// The first number after `key` on the first log line that starts with two spaces and `key` (the
/// banners' derived numbers), or after "= " on it with `after_equals` (e.g. "... = 60000 cells");
/// 0 if none.
double banner_number(const std::string& log, const std::string& key, bool after_equals = false);

}  // namespace lbdem::studies

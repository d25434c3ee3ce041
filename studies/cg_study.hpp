#pragma once
// `./lbdem study cg`: the coarse-graining adequacy report for any config. The user's case runs at
// each size factor of --levels (coarse_grain.size_factor, under the config's rule or --rule), each
// into ROOT/cgL, from the coarsest (the cheapest, whose result comes first) to the finest; then
// each observable's window mean and fluctuation at every level is compared with the finest level's,
// with statistical errors from block averages (tools/src/window_stats.hpp), and the wall time of
// each level with its speed-up. docs/studies.md gives the method and reads an example.
#include <string>
#include <vector>

#include "studies/study_options.hpp"

namespace lbdem::studies {

/// A level's value against the reference's: the difference, relative to the reference's value,
/// in units of the combined standard error, and the verdict: "same" (|z| <= kCgSigma: no
/// difference the statistics can resolve), "close" (resolved, but within `tolerance` of the
/// reference's value), or "differs".
struct CgDifference {
  double diff = 0, rel = 0, z = 0;
  std::string verdict;
};
inline constexpr double kCgSigma = 2;         // about 95 % two-sided for normal errors
inline constexpr double kCgTolerance = 0.05;  // --tolerance's default
CgDifference cg_difference(double value, double err, double ref, double ref_err, double tolerance);

/// The case folder name of size factor l: "cg2", "cg1_5".
std::string cg_case_name(double l);

/// The observables a scenario's report compares when --observables is not given.
std::vector<std::string> cg_default_observables(const std::string& scenario);

int run_cg_study(const StudyOptions& opt);

}  // namespace lbdem::studies

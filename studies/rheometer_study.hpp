#pragma once
// `./lbdem study rheometer`: the CG series of the rheometer study under each scaling rule, run one
// case after another into one folder, then a table (peak torque, steady torque with its statistical
// error, fluctuation, gap in parcel diameters, wall time per simulated second) and the torque plot.
// A case whose folder says "finished" is not run again; one that stopped is resumed.
#include <string>
#include <vector>

#include "studies/study_options.hpp"

namespace lbdem::studies {

struct TorqueSummary {
  double peak = 0;                    // largest 0.01 s block mean in the first revolution [N m]
  double steady = 0, steady_err = 0;  // mean after the first revolution, block standard error
  double fluctuation = 0;             // standard deviation of the samples there [N m]
  int blocks = 0;
};

/// Torque statistics of a time series (time [s], torque [N m]) for an impeller that starts at
/// `start` and turns at `rpm`: the steady window begins one revolution after the start. The
/// standard error comes from 0.05 s block means (about half a revolution at 600 rpm, longer than
/// the torque's correlation time of a few blade passages of a parcel).
TorqueSummary summarize_torque(const std::vector<double>& t, const std::vector<double>& torque,
                               double start, double rpm);

int run_rheometer_study(const StudyOptions& opt);

}  // namespace lbdem::studies

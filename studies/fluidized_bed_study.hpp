#pragma once
// `./lbdem study fluidized_bed`: the original-against-coarse-grain series (docs/studies.md):
// cohesionless CG 1-4 and wider CG 3, 4 beds; at Bond number 10 CG 1 and CG 2, 4 under the
// l^2 (tensile strength) and l^3 (Bond number) cohesion rules; CG 1 at Bond numbers 1 and 30. Each
// case runs (or resumes) into studies/fluidized_bed/NAME; then bed height and pressure drop of all
// cases are compared over the fluidized window (from 0.05 s after the ramp ends): overlay and power
// spectra (lbdem-compare-runs, tools/compare_runs.py), and a table (study.csv) of means with their
// block-average standard errors, fluctuations, parcels across and high, and wall time per
// simulated second.
#include "studies/study_options.hpp"

namespace lbdem::studies {

int run_fluidized_bed_study(const StudyOptions& opt);

}  // namespace lbdem::studies

#pragma once
// `./lbdem study validation`: published bubbling beds against their measurements
// (docs/validation.md). Each case runs (or resumes) a preset into studies/validation/NAME; then its
// comparison tool (tools/mueller_bed.py, tools/vanwachem_bed.py) writes the case's goals table
// (goals.csv: measured against computed, the goal and whether it is met) and figure
// (comparison.png), and the study joins the tables into validation.csv. Cases: the Mueller et al.
// bed with no-slip and with free-slip gas walls, the van Wachem et al. bed, and the free-slip
// Mueller bed coarse-grained at l = 1.5 and 2.
#include "studies/study_options.hpp"

namespace lbdem::studies {

int run_validation_study(const StudyOptions& opt);

}  // namespace lbdem::studies

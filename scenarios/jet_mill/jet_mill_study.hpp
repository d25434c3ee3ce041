#pragma once
// `./lbdem study jet_mill`: the coarse-graining series of DESIGN §1.3 (Scott, Borissova, Di Renzo
// & Ghadiri): CG-1, 2, 4, 8, 10 (n originals per parcel) on the scaled gas cells, each run (or
// resumed) into studies/jet_mill/NAME; the fixed-grid set (cg*_fixed), CG-10 at t_c/27
// (cg10_tc30) and CG-10 with 5 bar nozzles (cg10_p5bar) on request with --cases.
// Study time is the run's time less the 0.03 s gas spin-up; the figures' window is the study's
// 0.07-0.1 s. Then, per case, lbdem-jet-mill-maps (positions, speed map, wall-distance profile,
// gas mid-plane and radial profiles, speed in the jets' regions) and, across cases,
// lbdem-collision-stats (collision frequency, dissipated energy by mechanism) and
// lbdem-compare-runs (kinetic energy), drawn by tools/jet_mill_figures.py, and a table (study.csv).
// --quick runs every case on 1 mm cells to 4 ms of study time (a check of the chain, minutes).
#include "scenarios/study_options.hpp"

namespace lbdem::scenarios {

int run_jet_mill_study(const StudyOptions& opt);

}  // namespace lbdem::scenarios

#pragma once
// `./lbdem study jet_mill`: the coarse-graining series of the jet-mill study (Scott, Borissova, Di
// Renzo & Ghadiri): CG-1, 2, 4, 8, 10 (n originals per parcel) on the scaled gas cells with 5 bar
// nozzles (cg*_p5bar), each run (or resumed) into studies/jet_mill/NAME; on request with --cases
// incompressible 120 m/s jets (cg1 ... cg10), the fixed-grid sets (cg*_fixed, cg*_fixed_p5bar) and
// CG-10 with a DEM step near t_c/30 (cg10_tc30 at t_c/27, cg10_p5bar_tc30 at t_c/34).
// Study time is the run's time less the 0.03 s gas spin-up; the figures' window is the study's
// 0.07-0.1 s. Then, per case, lbdem-jet-mill-maps (positions, speed map, wall-distance profile,
// gas mid-plane and radial profiles, speed in the jets' regions) and, across cases,
// lbdem-collision-stats (collision frequency, dissipated energy by mechanism) and
// lbdem-compare-runs (kinetic energy), drawn by tools/jet_mill_figures.py, and a table (study.csv).
// --quick runs every case on 1 mm cells to 4 ms of study time (a check of the chain, minutes).
#include "studies/study_options.hpp"

namespace lbdem::studies {

int run_jet_mill_study(const StudyOptions& opt);

// The figures' window in run time: the study's 0.07-0.1 s (--quick: 2-4 ms) after the gas
// spin-up. A run writes its rows and snapshots on whole exchange cycles, and its last one less
// than a cycle past its end (0.1300024 s for 0.13 in cg4_p5bar: 3.8 us; a cycle is about 6 us at
// most in the presets). Without a pad the tools' closed window [from, to] dropped that row, and the
// window totals lost its last 0.41 ms (1.4 % in cg4_p5bar). Half a row interval is far above a
// cycle and below the next row: a run that ends at the window's end gives its last row and no
// other; one that went on gives at most one row past the end, the one nearest to it.
struct FigureWindow {
  double from, to;
};
FigureWindow figure_window(double spin_up, bool quick, double row_interval);

}  // namespace lbdem::studies

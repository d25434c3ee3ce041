#pragma once
// The jet mill's particle and gas fields of one run folder, as CSVs under PREFIX_*
// (tools/jet_mill_figures.py draws them; what lbdem-jet-mill-maps writes and the jet-mill study
// compares): positions seen from above at the end of the window (the study's Fig. 2), mean
// particle speed on x-y bins (Fig. 3) and against the distance from the outer wall (Fig. 6) over
// the window's particle snapshots, the gas speed on the mid-plane and its tangential and radial
// velocity against radius at the last gas snapshot of the window (Fig. 4), the gas crossing each
// cylinder about the axis averaged over the window's gas snapshots (the radial flow of the mass
// balance), and the mean speed in the jets' regions (mill_maps.hpp has the formulas).
#include <limits>
#include <string>
#include <vector>

#include "tools/src/mill_maps.hpp"
#include "tools/src/run_folder.hpp"

namespace lbdem::tools {

/// A jet's region unless told otherwise: 2 mm either side of its axis, 10 mm along it.
inline constexpr double kJetHalfWidth = 2e-3, kJetLength = 1e-2;  // [m]

struct MillMapOptions {
  std::string dir, prefix;  // the run folder; the output prefix (PREFIX_speed_map.csv, ...)
  double from = 0, to = std::numeric_limits<double>::infinity();  // [s], inclusive
  double bin = 1e-3;       // x-y bin of the speed map and radial bin of the gas [m]
  double wall_bin = 5e-4;  // bin of the wall-distance profile [m]
  std::vector<JetRegion> jets;
};

/// Writes the CSVs (each atomically) and returns the one-line summary; ToolError on a bad option,
/// a window without snapshots or a folder with neither particles.h5 nor fluid.h5. A run without
/// particles gets the gas's CSVs only, and NaN for the particles' figures in the summary.
std::string write_mill_maps(const MillMapOptions& o);

}  // namespace lbdem::tools

#pragma once
// One timeseries column of several runs over a window: mean with its block-average error,
// fluctuation with its error, and the power spectrum (what lbdem-compare-runs prints and the
// studies compare). window_stats.hpp and spectrum.hpp give the methods.
#include <limits>
#include <string>
#include <vector>

#include "tools/src/run_folder.hpp"
#include "tools/src/spectrum.hpp"
#include "tools/src/window_stats.hpp"

namespace lbdem::tools {

/// Fewer samples in a window give block errors from under 2 blocks of 8 and a spectrum of a
/// handful of bins: analyse_run refuses them.
inline constexpr std::size_t kMinWindowSamples = 16;

struct WindowOptions {
  std::string column;
  double from = -std::numeric_limits<double>::infinity();  // [s]
  double to = std::numeric_limits<double>::infinity();     // [s], inclusive
  double block_length = 0;                                 // [s]; 0: automatic
  std::size_t segments = 1;                                // Welch segments of the spectrum
};

struct RunStats {
  std::string dir, label;
  double size_factor = 1, ta = 0, tb = 0, dt = 0;  // window's first and last row, spacing [s]
  bool resampled = false;  // rows not evenly spaced: interpolated at the median spacing
  Moments m;
  BlockError err;      // of the mean
  BlockError std_err;  // of the fluctuation (fluctuation_error)
  Spectrum psd;
};

/// The statistics of `o.column` of `run` over the window; ToolError if the window holds fewer
/// than kMinWindowSamples rows or a value that is not finite.
RunStats analyse_run(const RunFolder& run, const std::string& label, const WindowOptions& o);

/// The printed table: each run's window, samples, mean and error, fluctuation and error, block
/// length, peak frequency, and its mean's difference from the first run's in combined errors.
std::string comparison_table(const std::string& column, const std::vector<RunStats>& res);

/// PREFIX_stats.csv and PREFIX_spectra.csv (tools/compare_runs.py plots them), each atomically.
void write_comparison(const std::string& prefix, const std::string& column,
                      const std::vector<RunStats>& res);

}  // namespace lbdem::tools

// lbdem-compare-runs: one timeseries column of several runs over a window: mean with its block-
// average error, fluctuation, and the power spectrum (FFTW), as a table and two CSVs
// (tools/src/run_comparison.hpp).
#include "tools/src/run_comparison.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace lbdem::tools;

namespace {

struct Options {
  std::vector<std::string> dirs, labels;
  std::string column = "torque_Nm", out;
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
  double block_length = 0;  // [s]; 0: automatic
  std::size_t segments = 1;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "lbdem-compare-runs: one column of several runs' timeseries.csv over a window [--from, "
      "--to]: mean, fluctuation (sample standard deviation), the standard error of the mean from "
      "block averages, and the one-sided power spectral density.\n"
      "Block length: automatic by Flyvbjerg & Petersen (1989) blocking: lengths of 1, 2, 4, ... "
      "samples while at least 8 blocks remain; the first length whose error agrees with those at "
      "twice and four times it within their statistical uncertainty 1/sqrt(2(n_blocks-1)) is the "
      "plateau, and the largest of the three errors is reported. Without a plateau the longest "
      "length with 8 blocks is used and the table says so (the error may then be low: lengthen "
      "the window). --block-length fixes it instead. 'vs 1st' is the difference of each mean from "
      "the first run's in combined standard errors. The fluctuation's standard error is the same "
      "blocking applied to the squared deviations (the error of the variance), halved and "
      "divided by the standard deviation (delta method).\n"
      "Spectrum: FFTW r2c of the linearly detrended, periodic-Hann-windowed signal, S = 2 dt "
      "|X|^2 / sum(w^2) [unit^2/Hz] (sum S df = windowed variance); --segments K averages K "
      "half-overlapping segments (Welch).\n"
      "--out PREFIX writes PREFIX_stats.csv and PREFIX_spectra.csv; plot them with "
      "/usr/bin/python3 tools/compare_runs.py PREFIX"};
  Options o;
  app.add_option("RUN_DIR", o.dirs, "run folders, e.g. CG 1, 1.6 and 2")->required();
  app.add_option("--column", o.column, "timeseries column")->capture_default_str();
  app.add_option("--from", o.from, "window start [s] (default: first row)");
  app.add_option("--to", o.to,
                 "window end [s], inclusive (default: last row; a run writes its last row up to "
                 "an exchange cycle past its end time, so a window ending there needs a pad)");
  app.add_option("--out", o.out, "prefix of the output CSVs (default: print only)");
  app.add_option("--label", o.labels, "label per run, in order (default: \"l = <size_factor>\")")
      ->allow_extra_args(false);
  app.add_option("--block-length", o.block_length, "fixed block length [s] (default: automatic)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--segments", o.segments, "Welch segments for the spectrum")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "lbdem-compare-runs: %s (see --help)\n", e.what());
    return kToolErrorExit;
  }
  return guarded_main("lbdem-compare-runs", [&] {
    check_window_and_labels(o.from, o.to, o.labels.size(), o.dirs.size());
    const WindowOptions w{o.column, o.from, o.to, o.block_length, o.segments};
    std::vector<RunStats> res;
    for (std::size_t k = 0; k < o.dirs.size(); ++k) {
      const RunFolder run = RunFolder::open(o.dirs[k]);
      res.push_back(analyse_run(run, run_label(o.labels, k, run.size_factor), w));
    }
    std::fputs(comparison_table(o.column, res).c_str(), stdout);
    if (!o.out.empty()) {
      write_comparison(o.out, o.column, res);
      std::printf("wrote %s_stats.csv and %s_spectra.csv\n", o.out.c_str(), o.out.c_str());
    }
    return 0;
  });
}

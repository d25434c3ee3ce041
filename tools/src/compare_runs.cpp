// lbdem-compare-runs: one timeseries column of several runs over a window: mean with its block-
// average error, fluctuation, and the power spectrum (FFTW), as a table and two CSVs.
#include "tools/src/run_folder.hpp"
#include "tools/src/spectrum.hpp"
#include "tools/src/window_stats.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace lbdem::tools;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Fewer samples give block errors from under 2 blocks of 8 and a spectrum of a handful of bins.
constexpr std::size_t kMinSamples = 16;

struct Options {
  std::vector<std::string> dirs, labels;
  std::string column = "torque_Nm", out;
  double from = -kInf, to = kInf;
  double block_length = 0;  // [s]; 0: automatic
  std::size_t segments = 1;
};

struct Result {
  std::string dir, label;
  double size_factor = 1, ta = 0, tb = 0, dt = 0;
  bool resampled = false;
  Moments m;
  BlockError err;
  BlockError std_err;  // of the fluctuation (window_stats.hpp: fluctuation_error)
  Spectrum psd;
};

// The window's samples on a uniform grid: the solver writes a row every whole number of steps, but
// a run's last row falls where the run ends, and a resumed run may change the interval. The FFT
// needs one spacing, so an irregular window is interpolated linearly at its median spacing.
std::vector<double> uniform_samples(const std::vector<double>& t, const std::vector<double>& x,
                                    IndexRange w, double& dt, bool& resampled) {
  std::vector<double> gaps;
  for (std::size_t k = w.begin + 1; k < w.end; ++k) gaps.push_back(t[k] - t[k - 1]);
  std::nth_element(gaps.begin(), gaps.begin() + std::ptrdiff_t(gaps.size() / 2), gaps.end());
  dt = gaps[gaps.size() / 2];
  std::vector<double> y(x.begin() + std::ptrdiff_t(w.begin), x.begin() + std::ptrdiff_t(w.end));
  resampled = false;
  for (std::size_t k = w.begin + 1; k < w.end; ++k)
    resampled = resampled || std::abs(t[k] - t[k - 1] - dt) > 1e-6 * dt;
  if (!resampled) return y;
  const double t0 = t[w.begin];
  const auto n = std::size_t(std::floor((t[w.end - 1] - t0) / dt + 1e-9)) + 1;
  std::vector<double> u(n);
  std::size_t j = w.begin;
  for (std::size_t k = 0; k < n; ++k) {
    const double tk = t0 + double(k) * dt;
    while (j + 2 < w.end && t[j + 1] < tk) ++j;
    const double s = (tk - t[j]) / (t[j + 1] - t[j]);
    u[k] = x[j] + std::clamp(s, 0.0, 1.0) * (x[j + 1] - x[j]);
  }
  return u;
}

Result analyse(const RunFolder& run, const std::string& label, const Options& o) {
  const auto& t = run.time();
  const auto& x = run.series.column(o.column);
  const IndexRange w = select_window(t, o.from, o.to);
  if (w.size() < kMinSamples)
    throw ToolError(window_error(run, o.from, o.to, w.size(), kMinSamples));
  for (std::size_t k = w.begin; k < w.end; ++k)
    if (!std::isfinite(x[k]))
      throw ToolError(o.column + " is not finite at t = " + std::to_string(t[k]) + " s in " +
                      run.series.source);
  Result r;
  r.dir = run.dir, r.label = label, r.size_factor = run.size_factor;
  r.ta = t[w.begin], r.tb = t[w.end - 1];
  const auto y = uniform_samples(t, x, w, r.dt, r.resampled);
  if (r.resampled)
    std::fprintf(stderr,
                 "lbdem-compare-runs: %s: rows not evenly spaced in the window; "
                 "interpolated at dt = %g s\n",
                 run.dir.c_str(), r.dt);
  r.m = moments(y);
  const std::size_t fixed =
      o.block_length > 0 ? std::size_t(std::max(1.0, std::round(o.block_length / r.dt))) : 0;
  r.err = fixed > 0 ? fixed_block_error(y, fixed) : auto_block_error(y);
  r.std_err = fluctuation_error(y, fixed);
  r.psd = one_sided_psd(y, r.dt, o.segments);
  return r;
}

void write_csvs(const std::string& prefix, const std::string& column,
                const std::vector<Result>& res) {
  const std::string stats = prefix + "_stats.csv", spectra = prefix + "_spectra.csv";
  std::ofstream s(stats), p(spectra);
  if (!s) throw ToolError("cannot write " + stats);
  if (!p) throw ToolError("cannot write " + spectra);
  s << "run_dir,label,size_factor,column,t_from_s,t_to_s,samples,dt_s,mean,stderr_mean,std,"
       "block_length_s,blocks,plateau,peak_frequency_Hz,psd_integral,resampled,stderr_std\n";
  p << "label,frequency_Hz,psd_per_Hz\n";
  s.precision(9);
  p.precision(9);
  for (const auto& r : res) {
    double integral = 0;
    for (double v : r.psd.psd) integral += v * r.psd.df;
    s << r.dir << ',' << '"' << r.label << '"' << ',' << r.size_factor << ',' << column << ','
      << r.ta << ',' << r.tb << ',' << r.m.n << ',' << r.dt << ',' << r.m.mean << ','
      << r.err.stderr_mean << ',' << r.m.std << ',' << double(r.err.block) * r.dt << ','
      << r.err.blocks << ',' << (r.err.plateau ? 1 : 0) << ',' << peak_frequency(r.psd) << ','
      << integral << ',' << (r.resampled ? 1 : 0) << ',' << r.std_err.stderr_mean << '\n';
    for (std::size_t k = 0; k < r.psd.psd.size(); ++k)
      p << '"' << r.label << '"' << ',' << r.psd.frequency[k] << ',' << r.psd.psd[k] << '\n';
  }
  std::printf("wrote %s and %s\n", stats.c_str(), spectra.c_str());
}

void print_table(const std::string& column, const std::vector<Result>& res) {
  std::printf(
      "%s: mean ± standard error (block averages), fluctuation (standard deviation) ± its "
      "standard error\n",
      column.c_str());
  std::printf("%-12s %17s %8s %12s %12s %12s %12s %9s %7s %10s %9s\n", "label", "window [s]",
              "samples", "mean", "± stderr", "std", "± stderr", "block[s]", "blocks", "peak f[Hz]",
              "vs 1st");
  for (const auto& r : res) {
    const auto& f = res.front();
    const double z = (r.m.mean - f.m.mean) / std::hypot(r.err.stderr_mean, f.err.stderr_mean);
    char window[40];
    std::snprintf(window, sizeof window, "%.4g-%.4g", r.ta, r.tb);
    std::printf("%-12s %17s %8zu %12.5g %12.3g %12.5g %12.3g %9.3g %7zu %10.4g %8.2fσ%s\n",
                r.label.c_str(), window, r.m.n, r.m.mean, r.err.stderr_mean, r.m.std,
                r.std_err.stderr_mean, double(r.err.block) * r.dt, r.err.blocks,
                peak_frequency(r.psd), &r == &f ? 0.0 : z,
                r.err.plateau ? "" : "  (no plateau: error may be low)");
  }
}

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
    std::vector<Result> res;
    for (std::size_t k = 0; k < o.dirs.size(); ++k) {
      const RunFolder run = RunFolder::open(o.dirs[k]);
      res.push_back(analyse(run, run_label(o.labels, k, run.size_factor), o));
    }
    print_table(o.column, res);
    if (!o.out.empty()) write_csvs(o.out, o.column, res);
    return 0;
  });
}

#include "tools/src/run_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/h5.hpp"

namespace lbdem::tools {

namespace {

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

}  // namespace

RunStats analyse_run(const RunFolder& run, const std::string& label, const WindowOptions& o) {
  const auto& t = run.time();
  const auto& x = run.series.column(o.column);
  const IndexRange w = select_window(t, o.from, o.to);
  if (w.size() < kMinWindowSamples)
    throw ToolError(window_error(run, o.from, o.to, w.size(), kMinWindowSamples));
  for (std::size_t k = w.begin; k < w.end; ++k)
    if (!std::isfinite(x[k]))
      throw ToolError(o.column + " is not finite at t = " + std::to_string(t[k]) + " s in " +
                      run.series.source);
  RunStats r;
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

void write_comparison(const std::string& prefix, const std::string& column,
                      const std::vector<RunStats>& res) {
  std::ostringstream s, p;
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
  write_file_atomic(prefix + "_stats.csv", s.str());
  write_file_atomic(prefix + "_spectra.csv", p.str());
}

std::string comparison_table(const std::string& column, const std::vector<RunStats>& res) {
  std::string out = column +
                    ": mean ± standard error (block averages), fluctuation (standard deviation) ± "
                    "its standard error\n";
  char line[512];
  std::snprintf(line, sizeof line, "%-12s %17s %8s %12s %12s %12s %12s %9s %7s %10s %9s\n", "label",
                "window [s]", "samples", "mean", "± stderr", "std", "± stderr", "block[s]",
                "blocks", "peak f[Hz]", "vs 1st");
  out += line;
  for (const auto& r : res) {
    const auto& f = res.front();
    const double z = (r.m.mean - f.m.mean) / std::hypot(r.err.stderr_mean, f.err.stderr_mean);
    char window[40];
    std::snprintf(window, sizeof window, "%.4g-%.4g", r.ta, r.tb);
    std::snprintf(line, sizeof line,
                  "%-12s %17s %8zu %12.5g %12.3g %12.5g %12.3g %9.3g %7zu %10.4g %8.2fσ%s\n",
                  r.label.c_str(), window, r.m.n, r.m.mean, r.err.stderr_mean, r.m.std,
                  r.std_err.stderr_mean, double(r.err.block) * r.dt, r.err.blocks,
                  peak_frequency(r.psd), &r == &f ? 0.0 : z,
                  r.err.plateau ? "" : "  (no plateau: error may be low)");
    out += line;
  }
  return out;
}

}  // namespace lbdem::tools

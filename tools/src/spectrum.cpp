#include "tools/src/spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace lbdem::tools {

std::vector<double> detrend_linear(std::span<const double> x) {
  const std::size_t n = x.size();
  std::vector<double> y(x.begin(), x.end());
  if (n < 2) {
    std::fill(y.begin(), y.end(), 0.0);
    return y;
  }
  // Least squares about the centred index c = k − (n−1)/2, where Σc = 0 decouples mean and slope.
  const double mid = 0.5 * double(n - 1);
  double mean = 0, sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < n; ++k) mean += x[k];
  mean /= double(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double c = double(k) - mid;
    sxy += c * (x[k] - mean);
    sxx += c * c;
  }
  const double slope = sxy / sxx;
  for (std::size_t k = 0; k < n; ++k) y[k] = x[k] - mean - slope * (double(k) - mid);
  return y;
}

std::vector<double> hann_periodic(std::size_t n) {
  std::vector<double> w(n);
  for (std::size_t k = 0; k < n; ++k)
    w[k] = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * double(k) / double(n)));
  return w;
}

double windowed_variance(std::span<const double> x) {
  const auto y = detrend_linear(x);
  const auto w = hann_periodic(x.size());
  double num = 0, s2 = 0;
  for (std::size_t k = 0; k < y.size(); ++k)
    num += (w[k] * y[k]) * (w[k] * y[k]), s2 += w[k] * w[k];
  return num / s2;
}

namespace {
// Owns one FFTW plan and its buffers; FFTW_ESTIMATE plans without timing trial transforms, which
// is faster than any measured plan for the few transforms a tool run makes.
class RealDft {
 public:
  explicit RealDft(std::size_t n) : in_(n), out_(n / 2 + 1) {
    plan_ = fftw_plan_dft_r2c_1d(int(n), in_.data(), reinterpret_cast<fftw_complex*>(out_.data()),
                                 FFTW_ESTIMATE);
    if (!plan_) throw std::runtime_error("FFTW: no plan for length " + std::to_string(n));
  }
  ~RealDft() { fftw_destroy_plan(plan_); }
  RealDft(const RealDft&) = delete;
  RealDft& operator=(const RealDft&) = delete;
  std::vector<double>& input() { return in_; }
  const std::vector<std::complex<double>>& run() {
    fftw_execute(plan_);
    return out_;
  }

 private:
  std::vector<double> in_;
  std::vector<std::complex<double>>
      out_;  // layout-compatible with fftw_complex (FFTW manual 4.1.1)
  fftw_plan plan_ = nullptr;
};
}  // namespace

Spectrum one_sided_psd(std::span<const double> x, double dt, std::size_t segments) {
  segments = std::max<std::size_t>(1, segments);
  // K segments of length L overlapping by L/2 span (K + 1) L / 2 samples.
  const std::size_t len = segments == 1 ? x.size() : 2 * x.size() / (segments + 1);
  if (len < 4)
    throw std::invalid_argument("spectrum: " + std::to_string(x.size()) + " samples in " +
                                std::to_string(segments) + " segment(s); need >= 4 per segment");
  if (!(dt > 0)) throw std::invalid_argument("spectrum: sample interval must be > 0");
  const std::size_t nf = len / 2 + 1;
  Spectrum s;
  s.segment = len;
  s.segments = segments;
  s.df = 1.0 / (double(len) * dt);
  s.frequency.resize(nf);
  for (std::size_t k = 0; k < nf; ++k) s.frequency[k] = double(k) * s.df;
  s.psd.assign(nf, 0.0);
  const auto w = hann_periodic(len);
  double s2 = 0;
  for (double v : w) s2 += v * v;
  RealDft dft(len);
  const std::size_t hop = segments == 1 ? 0 : (x.size() - len) / (segments - 1);
  for (std::size_t seg = 0; seg < segments; ++seg) {
    const auto y = detrend_linear(x.subspan(seg * hop, len));
    for (std::size_t k = 0; k < len; ++k) dft.input()[k] = w[k] * y[k];
    const auto& X = dft.run();
    for (std::size_t k = 0; k < nf; ++k) {
      const bool edge = k == 0 || (len % 2 == 0 && k == len / 2);  // bins without a mirror image
      s.psd[k] += (edge ? 1.0 : 2.0) * dt * std::norm(X[k]) / s2;
    }
  }
  for (double& v : s.psd) v /= double(segments);
  return s;
}

double peak_frequency(const Spectrum& s) {
  if (s.psd.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  const auto it = std::max_element(s.psd.begin() + 1, s.psd.end());
  return s.frequency[std::size_t(it - s.psd.begin())];
}

}  // namespace lbdem::tools

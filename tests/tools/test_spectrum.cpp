// One-sided PSD (FFTW r2c, linear detrend, periodic Hann) against analytic references: Parseval's
// identity, the Hann window's power, a sine's peak, and the flat level 2σ²Δt of white noise.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "tools/src/spectrum.hpp"

using namespace lbdem::tools;

namespace {
double integral(const Spectrum& s) {
  double sum = 0;
  for (double v : s.psd) sum += v * s.df;
  return sum;
}
std::vector<double> noisy_ramp(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> eps(0.0, 0.3);
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = 5.0 + 2e-3 * double(k) + eps(rng);
  return x;
}
}  // namespace

TEST_CASE("Periodic Hann window keeps 3/8 of the power", "[tools]") {
  // Σ (½ − ½cos θ_n)² = N/4 + (1/4) Σ cos² θ_n = N/4 + N/8 for θ_n = 2πn/N, N > 2 (Harris 1978).
  for (std::size_t n : {8, 999, 1000}) {
    double s2 = 0;
    for (double w : hann_periodic(n)) s2 += w * w;
    CHECK(s2 == Approx(3.0 * double(n) / 8.0).epsilon(1e-13));
  }
}

TEST_CASE("Linear detrend removes a straight line exactly", "[tools]") {
  std::vector<double> x(101);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = -4.0 + 0.25 * double(k);
  for (double v : detrend_linear(x)) CHECK(std::abs(v) < 1e-13);  // 25 ulp of the largest value
}

TEST_CASE("PSD obeys Parseval: sum S df equals the windowed variance", "[tools]") {
  // Σ_k S_k Δf = Σ_n (w_n y_n)² / Σ w_n² exactly for the scaling S_k = c_k Δt |X_k|² / Σ w²; what
  // is left is floating-point rounding of the DFT, O(ε log N) relative.
  const double dt = 2e-3;
  for (std::size_t n : {1000, 999, 64}) {
    const auto x = noisy_ramp(n, unsigned(n));
    const Spectrum s = one_sided_psd(x, dt);
    CHECK(s.df == Approx(1.0 / (double(n) * dt)).epsilon(1e-15));
    CHECK(s.psd.size() == n / 2 + 1);
    CHECK(integral(s) == Approx(windowed_variance(x)).epsilon(1e-12));
  }
  // Welch: the average of the segments' spectra integrates to the average windowed variance of
  // the segments, here 3 segments of 500 samples at offsets 0, 250, 500 of 1000.
  const auto x = noisy_ramp(1000, 9);
  const Spectrum s = one_sided_psd(x, dt, 3);
  REQUIRE(s.segment == 500);
  double mean_var = 0;
  for (std::size_t seg = 0; seg < 3; ++seg)
    mean_var += windowed_variance(std::span<const double>(x).subspan(seg * 250, 500)) / 3;
  CHECK(integral(s) == Approx(mean_var).epsilon(1e-12));
}

TEST_CASE("A sine on a bin gives its peak frequency and power", "[tools]") {
  const std::size_t n = 4096, k0 = 200;
  const double dt = 1e-3, a = 3.0;
  const double f0 = double(k0) / (double(n) * dt);
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k)
    x[k] = 0.7 + a * std::sin(2 * std::numbers::pi * f0 * double(k) * dt + 0.4);
  const Spectrum s = one_sided_psd(x, dt);
  CHECK(peak_frequency(s) == Approx(f0).epsilon(1e-12));
  // Hann's DFT is N/2 at offset 0 and −N/4 at ±1 bin, so |X| = aN/4 at k0 and aN/8 beside it:
  // S(k0) = 2Δt(aN/4)²/(3N/8) = a²NΔt/3, S(k0±1) = a²NΔt/12, and the three bins hold a²/2, the
  // sine's variance. The line the detrend fits to a whole-period sine is O(a/k0) and leaks into
  // bin k0 only through Hann's sidelobes (falling as k^-3), far below the 1e-6 asked here.
  const double peak = a * a * double(n) * dt / 3;
  CHECK(s.psd[k0] == Approx(peak).epsilon(1e-6));
  CHECK(s.psd[k0 - 1] == Approx(peak / 4).epsilon(1e-6));
  CHECK(s.psd[k0 + 1] == Approx(peak / 4).epsilon(1e-6));
  CHECK((s.psd[k0 - 1] + s.psd[k0] + s.psd[k0 + 1]) * s.df == Approx(a * a / 2).epsilon(1e-6));
}

TEST_CASE("White noise has the flat one-sided level 2 sigma^2 dt", "[tools]") {
  const std::size_t n = 1 << 14;
  const double dt = 5e-4, sigma = 0.8;
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> eps(0.0, sigma);
  std::vector<double> x(n);
  for (double& v : x) v = eps(rng);
  const Spectrum s = one_sided_psd(x, dt);
  double mean = 0;
  const std::size_t lo = 4, hi = s.psd.size() - 1;  // away from k = 0 (detrend) and Nyquist
  for (std::size_t k = lo; k < hi; ++k) mean += s.psd[k];
  mean /= double(hi - lo);
  // Each bin is exponential (relative sd 1). Hann correlates the bins' DFTs by ρ_j, the Fourier
  // coefficients of w² over Σw²: ρ_1 = (1/4)/(3/8) = 2/3, ρ_2 = (1/16)/(3/8) = 1/6; their powers
  // by ρ_j². The mean of M bins then has relative variance (1 + 2·4/9 + 2/36)/M = 1.94/M, i.e. a
  // relative sd of 1.5 % for M = 8187; 5 sd give the tolerance.
  CHECK(mean == Approx(2 * sigma * sigma * dt).epsilon(0.077));
}

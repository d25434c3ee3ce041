// Window statistics and block-average errors against closed forms: the standard error of the mean
// of white noise, σ/√N, and of a first-order autoregressive process, whose correlated samples make
// the naive σ/√N too small by √((1+φ)/(1−φ)) (Flyvbjerg & Petersen 1989, J. Chem. Phys. 91, 461).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "tools/src/window_stats.hpp"

using namespace lbdem::tools;

namespace {
// Stationary AR(1), x_k = φ x_{k−1} + √(1−φ²) σ ε_k, started from its stationary distribution, so
// every sample has variance σ² and correlation φ^|j| with x_{k+j} (φ = 0: white noise).
std::vector<double> ar1(std::size_t n, double phi, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> eps(0.0, 1.0);
  std::vector<double> x(n);
  x[0] = sigma * eps(rng);
  for (std::size_t k = 1; k < n; ++k)
    x[k] = phi * x[k - 1] + std::sqrt(1 - phi * phi) * sigma * eps(rng);
  return x;
}
}  // namespace

TEST_CASE("Window selection and moments by hand", "[tools]") {
  const std::vector<double> t = {0.0, 0.1, 0.2, 0.3, 0.4};
  const IndexRange w = select_window(t, 0.1, 0.3);  // closed interval: 0.1, 0.2, 0.3
  CHECK(w.begin == 1);
  CHECK(w.size() == 3);
  CHECK(select_window(t, 0.45, 1.0).size() == 0);
  // 1, 2, 3, 4: mean 2.5, sample variance Σ(x−2.5)²/3 = 5/3; exact in binary up to one rounding.
  const std::vector<double> x = {1e6 + 1, 1e6 + 2, 1e6 + 3, 1e6 + 4};  // offset ≫ spread: 2 passes
  const Moments m = moments(x);
  CHECK(m.mean == Approx(1e6 + 2.5).epsilon(1e-15));
  CHECK(m.std == Approx(std::sqrt(5.0 / 3.0)).epsilon(1e-9));  // 1e6 offset costs ~1e-10 relative
}

TEST_CASE("Block standard error of white noise is sigma/sqrt(N)", "[tools]") {
  const std::size_t n = 1 << 16;
  const double sigma = 2.0;
  const auto x = ar1(n, 0.0, sigma, 12345);
  const double expected = sigma / std::sqrt(double(n));
  // An estimate from n_B independent block means has relative standard deviation
  // 1/√(2(n_B−1)); 4 of them bound a fixed-seed draw with a two-sided probability of 6e-5.
  for (std::size_t block : {1, 16, 256}) {
    const std::size_t nb = n / block;
    const double tol = 4 * block_error_uncertainty(nb);
    CHECK(block_standard_error(x, block) == Approx(expected).epsilon(tol));
  }
  const BlockError e = auto_block_error(x);
  CHECK(e.plateau);
  CHECK(e.stderr_mean == Approx(expected).epsilon(4 * block_error_uncertainty(e.blocks)));
  CHECK(std::isnan(block_standard_error(x, n)));  // one block: no spread to measure
}

TEST_CASE("Automatic blocking recovers the correlated error of an AR(1) signal", "[tools]") {
  const std::size_t n = 1 << 18;
  const double phi = 0.8, sigma = 1.5;
  const auto x = ar1(n, phi, sigma, 777);
  // Var(mean) → σ²/N (1+φ)/(1−φ) for N ≫ 1/(1−φ): a factor 3 above the naive σ/√N here.
  const double expected = sigma / std::sqrt(double(n)) * std::sqrt((1 + phi) / (1 - phi));
  const BlockError e = auto_block_error(x);
  REQUIRE(e.plateau);
  // Blocks of b samples underestimate the variance of the mean by the closed-form deficit
  // 2φ(1−φ^b) / (b(1−φ)²) out of (1+φ)/(1−φ); at the chosen b that bias is added to the
  // statistical tolerance of 4 relative standard deviations.
  const double b = double(e.block);
  const double deficit =
      2 * phi * (1 - std::pow(phi, b)) / (b * (1 - phi) * (1 - phi)) / ((1 + phi) / (1 - phi));
  CHECK(e.block >= 16);  // correlation time 1/(1−φ) = 5 samples: short blocks must be rejected
  CHECK(e.stderr_mean ==
        Approx(expected).epsilon(4 * block_error_uncertainty(e.blocks) + 0.5 * deficit));
  // The naive white-noise error is far off, which is why blocking exists.
  CHECK(block_standard_error(x, 1) < 0.4 * expected);
}

TEST_CASE("Error of the fluctuation: white noise and AR(1) against closed forms", "[tools]") {
  // The sample variance of n Gaussian samples with correlation phi^|j| has
  // Var(s^2) -> 2 sigma^4 / n (1 + phi^2) / (1 - phi^2) (the squares are correlated as phi^2|j|),
  // so se(s) = sigma / sqrt(2 n) sqrt((1 + phi^2) / (1 - phi^2)). Tolerance as for the mean's
  // error: 4 relative standard deviations of a block estimate, plus half the blocks' deficit
  // (computed with phi^2, the squares' correlation).
  const std::size_t n = 1 << 18;
  const double sigma = 1.5;
  for (const double phi : {0.0, 0.8}) {
    CAPTURE(phi);
    const auto x = ar1(n, phi, sigma, 4242);
    const double p2 = phi * phi;
    const double expected = sigma / std::sqrt(2.0 * double(n)) * std::sqrt((1 + p2) / (1 - p2));
    const BlockError e = fluctuation_error(x);
    REQUIRE(e.plateau);
    const double b = double(e.block);
    const double deficit =
        p2 > 0 ? 2 * p2 * (1 - std::pow(p2, b)) / (b * (1 - p2) * (1 - p2)) / ((1 + p2) / (1 - p2))
               : 0.0;
    CHECK(e.stderr_mean ==
          Approx(expected).epsilon(4 * block_error_uncertainty(e.blocks) + 0.5 * deficit));
  }
  // The correlated case's error is larger than the white-noise formula by the factor above
  // (2.13): ignoring the correlation would understate it.
  const auto x = ar1(n, 0.8, sigma, 4242);
  CHECK(fluctuation_error(x).stderr_mean > 1.5 * sigma / std::sqrt(2.0 * double(n)));
  // A constant signal has no fluctuation and no error in it.
  const std::vector<double> flat(100, 3.0);
  CHECK(fluctuation_error(flat).stderr_mean == 0.0);
}

TEST_CASE("Fixed block length and too-short series", "[tools]") {
  const auto x = ar1(1000, 0.0, 1.0, 3);
  const BlockError f = fixed_block_error(x, 10);
  CHECK(f.block == 10);
  CHECK(f.blocks == 100);
  CHECK(f.stderr_mean == block_standard_error(x, 10));
  const std::vector<double> few(5, 1.0);
  const BlockError e = auto_block_error(few);
  CHECK_FALSE(e.plateau);
  CHECK(std::isnan(e.stderr_mean));
}

#pragma once
// Statistics of one sampled signal over a time window: mean, fluctuation, and the standard error of
// the mean from block averages (Flyvbjerg & Petersen 1989, J. Chem. Phys. 91, 461), which stays
// honest for correlated samples where σ/√N would understate the error.
#include <cstddef>
#include <span>
#include <vector>

namespace lbdem::tools {

/// Index range [begin, end) of the samples with t0 <= t <= t1 (t sorted ascending).
struct IndexRange {
  std::size_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
};
IndexRange select_window(std::span<const double> t, double t0, double t1);

struct Moments {
  std::size_t n = 0;
  double mean = 0;
  double std = 0;  // sample standard deviation (divisor n - 1): the fluctuation
};
Moments moments(std::span<const double> x);

/// Standard error of the mean from the means of consecutive blocks of `block` samples:
/// s_B / √n_B with s_B the sample standard deviation of the n_B = ⌊N / block⌋ block means (the
/// leftover N mod block samples are not used). NaN if fewer than 2 blocks.
double block_standard_error(std::span<const double> x, std::size_t block);

/// Relative standard deviation of a block standard error estimated from n_B blocks of independent
/// means, 1 / √(2 (n_B − 1)) (chi distribution with n_B − 1 degrees of freedom, large-n form).
double block_error_uncertainty(std::size_t blocks);

struct BlockError {
  double stderr_mean = 0;  // standard error of the mean [unit of x]
  std::size_t block = 1;   // chosen block length [samples]
  std::size_t blocks = 0;  // number of blocks at that length
  bool plateau = false;    // false: no plateau found, the error may be underestimated
};

/// Automatic block length, the blocking rule of Flyvbjerg & Petersen: block lengths 1, 2, 4, ...
/// while at least kMinBlocks blocks remain; the chosen one is the first b whose estimate agrees
/// with those at 2b and 4b within their combined statistical uncertainty (the plateau); of these
/// three the largest error is reported, which errs on the safe side of a slow rise. Without a
/// plateau, the longest block length with kMinBlocks blocks is taken and plateau = false.
inline constexpr std::size_t kMinBlocks = 8;
BlockError auto_block_error(std::span<const double> x);
/// Fixed block length (samples), e.g. from --block-length.
BlockError fixed_block_error(std::span<const double> x, std::size_t block);

/// Standard error of the fluctuation (the sample standard deviation s), in stderr_mean: s^2 is the
/// mean of y_k = n / (n - 1) (x_k - mean)^2, so the blocking above applied to y gives the error of
/// s^2 with the samples' correlation accounted for, and the delta method that of s,
/// se(s) = se(s^2) / (2 s). `block` 0: automatic, else a fixed block length [samples]. For white
/// Gaussian noise it tends to s / sqrt(2 (n - 1)).
BlockError fluctuation_error(std::span<const double> x, std::size_t block = 0);

}  // namespace lbdem::tools

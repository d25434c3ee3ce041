#include "tools/src/window_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lbdem::tools {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

IndexRange select_window(std::span<const double> t, double t0, double t1) {
  const auto lo = std::lower_bound(t.begin(), t.end(), t0);
  const auto hi = std::upper_bound(lo, t.end(), t1);
  return {std::size_t(lo - t.begin()), std::size_t(hi - t.begin())};
}

Moments moments(std::span<const double> x) {
  Moments m;
  m.n = x.size();
  if (m.n == 0) return {0, kNaN, kNaN};
  // Two passes: the one-pass sum of squares loses digits when the mean dominates (a torque
  // offset much larger than its fluctuation).
  double s = 0;
  for (double v : x) s += v;
  m.mean = s / double(m.n);
  double q = 0;
  for (double v : x) q += (v - m.mean) * (v - m.mean);
  m.std = m.n > 1 ? std::sqrt(q / double(m.n - 1)) : kNaN;
  return m;
}

double block_standard_error(std::span<const double> x, std::size_t block) {
  if (block == 0) return kNaN;
  const std::size_t nb = x.size() / block;
  if (nb < 2) return kNaN;
  std::vector<double> means(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    double s = 0;
    for (std::size_t k = 0; k < block; ++k) s += x[b * block + k];
    means[b] = s / double(block);
  }
  return moments(means).std / std::sqrt(double(nb));
}

double block_error_uncertainty(std::size_t blocks) {
  return blocks > 1 ? 1.0 / std::sqrt(2.0 * double(blocks - 1)) : kNaN;
}

BlockError fixed_block_error(std::span<const double> x, std::size_t block) {
  const std::size_t b = std::max<std::size_t>(1, block);
  return {block_standard_error(x, b), b, x.size() / b, true};
}

BlockError auto_block_error(std::span<const double> x) {
  struct Level {
    std::size_t block, blocks;
    double se;
  };
  std::vector<Level> levels;
  for (std::size_t b = 1; x.size() / b >= kMinBlocks; b *= 2)
    levels.push_back({b, x.size() / b, block_standard_error(x, b)});
  if (levels.empty()) return {kNaN, x.size(), 1, false};
  const auto agree = [](const Level& a, const Level& c) {
    const double ua = a.se * block_error_uncertainty(a.blocks);
    const double uc = c.se * block_error_uncertainty(c.blocks);
    return std::abs(a.se - c.se) <= std::hypot(ua, uc);
  };
  for (std::size_t k = 0; k + 2 < levels.size(); ++k) {
    const Level& l = levels[k];
    if (!agree(l, levels[k + 1]) || !agree(l, levels[k + 2])) continue;
    // The largest of the three agreeing estimates: conservative against a slow residual rise.
    const Level& m = *std::max_element(levels.begin() + k, levels.begin() + k + 3,
                                       [](const Level& a, const Level& c) { return a.se < c.se; });
    return {m.se, m.block, m.blocks, true};
  }
  const Level& last = levels.back();
  return {last.se, last.block, last.blocks, false};
}

BlockError fluctuation_error(std::span<const double> x, std::size_t block) {
  const Moments m = moments(x);
  if (m.n < 2) return {kNaN, 1, 0, false};
  const double c = double(m.n) / double(m.n - 1);
  std::vector<double> y(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) y[k] = c * (x[k] - m.mean) * (x[k] - m.mean);
  BlockError e = block > 0 ? fixed_block_error(y, block) : auto_block_error(y);
  e.stderr_mean = m.std > 0 ? e.stderr_mean / (2 * m.std) : 0.0;  // a constant signal: exact
  return e;
}

}  // namespace lbdem::tools

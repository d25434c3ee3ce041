#include "tools/src/collision_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

namespace lbdem::tools {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double per_parcel_frequency(double collisions, double parcels, double duration, Pair pair) {
  if (!(parcels > 0) || !(duration > 0)) return kNaN;
  const double partners = pair == Pair::particle_particle ? 2.0 : 1.0;
  return partners * collisions / (parcels * duration);
}

double per_original_frequency(double per_parcel, double size_factor) {
  return per_parcel / (size_factor * size_factor * size_factor);
}

double represented_originals(double parcels, double size_factor) {
  return parcels * size_factor * size_factor * size_factor;
}

double Histogram::total() const {
  return std::accumulate(counts.begin(), counts.end(), 0.0);
}

Histogram bin_values(std::span<const double> values, const std::vector<double>& edges) {
  Histogram h{edges, std::vector<double>(edges.size() > 1 ? edges.size() - 1 : 0, 0.0)};
  if (h.counts.empty()) return h;
  for (double v : values) {
    const auto it = std::upper_bound(edges.begin(), edges.end(), std::abs(v));
    const std::ptrdiff_t k = (it - edges.begin()) - 1;
    h.counts[std::size_t(std::clamp<std::ptrdiff_t>(k, 0, std::ptrdiff_t(h.counts.size()) - 1))] +=
        1;
  }
  return h;
}

double histogram_quantile(const Histogram& h, double q) {
  const double n = h.total();
  if (!(n > 0) || h.edges.size() != h.counts.size() + 1) return kNaN;
  const double target = std::clamp(q, 0.0, 1.0) * n;
  double below = 0;
  for (std::size_t k = 0; k < h.counts.size(); ++k) {
    if (below + h.counts[k] < target && k + 1 < h.counts.size()) {
      below += h.counts[k];
      continue;
    }
    const double frac = h.counts[k] > 0 ? std::clamp((target - below) / h.counts[k], 0.0, 1.0) : 0;
    const double a = h.edges[k], b = h.edges[k + 1];
    if (a > 0 && b > 0) return a * std::pow(b / a, frac);
    return a + frac * (b - a);
  }
  return kNaN;
}

GridSummary summarise_grid(std::span<const double> energy, std::size_t nz, std::size_t ny,
                           std::size_t nx, double z_lo, double z_hi) {
  GridSummary g;
  if (energy.size() != nz * ny * nx || energy.empty()) return {kNaN, kNaN, kNaN};
  g.total = std::accumulate(energy.begin(), energy.end(), 0.0);
  std::vector<double> sorted(energy.begin(), energy.end());
  std::sort(sorted.begin(), sorted.end(), std::greater<>());
  const std::size_t top = std::max<std::size_t>(1, (sorted.size() + 9) / 10);
  const double hot = std::accumulate(sorted.begin(), sorted.begin() + std::ptrdiff_t(top), 0.0);
  g.top_decile = g.total > 0 ? hot / g.total : kNaN;
  const double hz = (z_hi - z_lo) / double(nz);
  double weighted = 0;
  for (std::size_t z = 0; z < nz; ++z) {
    double layer = 0;
    for (std::size_t c = 0; c < ny * nx; ++c) layer += energy[z * ny * nx + c];
    weighted += layer * (z_lo + (double(z) + 0.5) * hz);
  }
  g.z_centroid = g.total > 0 ? weighted / g.total : kNaN;
  return g;
}

}  // namespace lbdem::tools

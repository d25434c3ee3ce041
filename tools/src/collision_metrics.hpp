#pragma once
// Pure formulas of the collision statistics tool: collision frequencies per parcel and per
// represented original particle, quantiles of binned impact speeds, and summaries of the spatial
// dissipation grid.
#include <cstddef>
#include <span>
#include <vector>

namespace lbdem::tools {

enum class Pair { particle_particle, particle_wall };

/// Collisions a single parcel takes part in per second: a particle–particle collision involves two
/// parcels (2 n / (N Δt)), a particle–wall collision one (n / (N Δt)). [1/s]
double per_parcel_frequency(double collisions, double parcels, double duration, Pair pair);

/// Per represented original particle: one parcel of size factor l stands for l³ originals, so its
/// collisions are shared among them, f_orig = f_parcel / l³. [1/s]
double per_original_frequency(double per_parcel, double size_factor);

/// Number of original particles the parcels represent, N l³.
double represented_originals(double parcels, double size_factor);

struct Histogram {
  std::vector<double> edges;   // bin edges [m/s], ascending, size = counts + 1
  std::vector<double> counts;  // impacts per bin
  double total() const;
};

/// Bins values on the given edges; values outside go to the first or last bin, as the solver's
/// own histograms do (dem/collision_stats.cpp).
Histogram bin_values(std::span<const double> values, const std::vector<double>& edges);

/// Quantile q in [0, 1] of a binned distribution. Within a bin the position is interpolated
/// linearly in log(v) where both edges are positive (the solver's bins are log-spaced), else
/// linearly. NaN for an empty histogram.
double histogram_quantile(const Histogram& h, double q);

/// Summary of a dissipation grid stored (nz, ny, nx) with x fastest.
struct GridSummary {
  double total = 0;       // Σ over cells [J]
  double top_decile = 0;  // share of the total in the hottest 10 % of cells [-]
  double z_centroid = 0;  // dissipation-weighted mean height of the cell centres [m]
};
GridSummary summarise_grid(std::span<const double> energy, std::size_t nz, std::size_t ny,
                           std::size_t nx, double z_lo, double z_hi);

}  // namespace lbdem::tools

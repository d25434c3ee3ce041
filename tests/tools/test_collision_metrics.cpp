// Collision frequencies per parcel and per represented original, binned quantiles and the grid
// summary, against hand-computed values.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "tools/src/collision_metrics.hpp"
#include "tools/src/run_folder.hpp"

using namespace lbdem::tools;

TEST_CASE("Per-parcel and per-original collision frequencies", "[tools]") {
  // 1000 collisions among 100 parcels in 2 s: each particle-particle collision involves two
  // parcels, so every parcel takes part in 2·1000/(100·2) = 10 per second; walls: 5 per second.
  const double pp = per_parcel_frequency(1000, 100, 2.0, Pair::particle_particle);
  const double pw = per_parcel_frequency(1000, 100, 2.0, Pair::particle_wall);
  CHECK(pp == Approx(10.0).epsilon(1e-15));
  CHECK(pw == Approx(5.0).epsilon(1e-15));
  // l = 2: one parcel stands for 8 originals, f_orig = f_parcel / 8; l = 1 changes nothing.
  CHECK(per_original_frequency(pp, 2.0) == Approx(1.25).epsilon(1e-15));
  CHECK(per_original_frequency(pp, 1.0) == pp);
  CHECK(represented_originals(100, 2.0) == Approx(800).epsilon(1e-15));
  // The conversion only re-divides the same collisions: f_orig × originals × T / 2 gives the
  // particle-particle count back for any l (here l = 1.6, as in the rheometer seed).
  const double l = 1.6;
  CHECK(per_original_frequency(pp, l) * represented_originals(100, l) * 2.0 / 2 ==
        Approx(1000).epsilon(1e-14));
  CHECK(std::isnan(per_parcel_frequency(5, 0, 1.0, Pair::particle_wall)));
  CHECK(std::isnan(per_parcel_frequency(5, 10, 0.0, Pair::particle_wall)));
}

TEST_CASE("Size factor from config.toml", "[tools]") {
  CHECK(size_factor_from_toml("[coarse_grain]\nsize_factor = 2.5\n", "a") == 2.5);
  // n originals per parcel: l = n^(1/3); 8 → 2 up to cbrt's last-bit rounding.
  CHECK(size_factor_from_toml("[coarse_grain]\nparticles_per_parcel = 8\n", "b") ==
        Approx(2.0).epsilon(1e-15));
  CHECK(size_factor_from_toml("[run]\nend_time = 1\n", "c") == 1.0);
  CHECK(default_label(1.6) == "l = 1.6");
  CHECK_THROWS_AS(size_factor_from_toml("[coarse_grain\n", "d"), ToolError);
}

TEST_CASE("Quantiles of a log-binned histogram", "[tools]") {
  // Counts 1, 2, 1 on edges 1, 10, 100, 1000: the median (2 of 4) is the middle of the second bin
  // in log v, √(10·100); all counts at or below 1000 for q = 1; q = 0 the first edge.
  Histogram h{{1, 10, 100, 1000}, {1, 2, 1}};
  CHECK(histogram_quantile(h, 0.5) == Approx(std::sqrt(1000.0)).epsilon(1e-14));
  CHECK(histogram_quantile(h, 1.0) == Approx(1000).epsilon(1e-14));
  CHECK(histogram_quantile(h, 0.0) == Approx(1).epsilon(1e-14));
  // A zero lower edge falls back to linear interpolation: bin [0, 2] holds everything.
  CHECK(histogram_quantile(Histogram{{0, 2}, {4}}, 0.25) == Approx(0.5).epsilon(1e-15));
  CHECK(std::isnan(histogram_quantile(Histogram{{1, 2}, {0}}, 0.5)));
  // Binning sorts |v| into [edge_k, edge_k+1) and clamps outliers into the end bins.
  const Histogram b = bin_values(std::vector<double>{0.5, 5, -50, 500, 5000, 10}, h.edges);
  CHECK(b.counts == std::vector<double>{2, 2, 2});
}

TEST_CASE("Dissipation grid summary", "[tools]") {
  // 10 cells stacked in z (nz = 10, ny = nx = 1) over z in [0, 1]: all energy in cell 7 and 9.
  std::vector<double> e(10, 0.0);
  e[7] = 3, e[9] = 1;
  const GridSummary g = summarise_grid(e, 10, 1, 1, 0.0, 1.0);
  CHECK(g.total == 4);
  CHECK(g.top_decile == Approx(0.75).epsilon(1e-15));  // the hottest 1 of 10 cells holds 3 of 4
  CHECK(g.z_centroid == Approx((3 * 0.75 + 1 * 0.95) / 4).epsilon(1e-15));
}

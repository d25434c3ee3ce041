// Collision statistics: counts and histograms always; one row per contact only inside the window
// and up to the row budget, with the overflow counted (a dense bed must not fill the disk unasked).
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/h5.hpp"
#include "dem/collision_stats.hpp"

using namespace lbdem;

TEST_CASE("collision rows respect the time window and the row budget", "[dem][collisions]") {
  dem::CollisionSettings s;
  s.rows = true;
  s.rows_t0 = 1.0;
  s.rows_t1 = 2.0;
  s.row_budget = 3;
  dem::Domain d;
  dem::CollisionStats stats;
  stats.setup(s, d);
  dem::ContactTally t;
  t.e_dissipated = 1e-6;
  const dem::ContactRecord r{.vn_impact = 0.3};
  for (double time : {0.5, 1.1, 1.2, 1.5, 1.9, 2.5}) {
    stats.on_start(false, 0.3, 0.01);
    stats.on_end(t, r, time, 1, 2, Vec3(0.5, 0.5, 0.5));
  }
  CHECK(stats.started_pp() == 6);
  CHECK(stats.rows_dropped() == 1);              // 4 ends inside [1, 2], budget 3
  stats.add_dissipated(1e-6, 2e-6, 3e-6, 4e-6);  // the solver's ledger, written as totals
  const auto path = (std::filesystem::temp_directory_path() /
                     ("lbdem_collisions_" + std::to_string(::getpid()) + ".h5"))
                        .string();
  stats.write(path, 3.0);
  const H5In f(path);
  CHECK(f.doubles("/rows/t_end_s") == std::vector<double>{1.1, 1.2, 1.5});
  CHECK(f.doubles("/rows/dissipated_J") == std::vector<double>{1e-6, 1e-6, 1e-6});
  CHECK(f.attr_double("dissipated_tangential_damping_J", "/totals") == 2e-6);
  const auto counts = f.int64s("/histograms/impact_normal_speed_counts_pp");
  std::int64_t total = 0;
  for (auto c : counts) total += c;
  CHECK(total == 6);
  std::filesystem::remove(path);
}

// The jet mill study's figure window (scenarios/jet_mill/jet_mill_study.hpp) on the rows a real
// run wrote: cg4_p5bar's timeseries.csv and config.toml, kept in results/ (2026-11-25). Its driver
// wrote a row every 131 exchange cycles (655 DEM steps of 0.7639 us: 0.50035 ms apart) and one at
// its last step, 0.1300024 s for the end time 0.13 s. The window must end at that last row, or the
// window totals lose the last 0.41 ms (1.4 %). (A rerun of cg4_p5bar whose last step lands on
// 0.13 s exactly would leave nothing to drop: keep a run here whose last row lies past its end.)
#include <catch2/catch.hpp>

#include "core/config.hpp"
#include "scenarios/common/dem_driver.hpp"
#include "scenarios/jet_mill/jet_mill_study.hpp"
#include "tools/src/run_folder.hpp"
#include "tools/src/window_stats.hpp"

using lbdem::Config;
using lbdem::scenarios::figure_window;
using lbdem::scenarios::OutputSettings;
using lbdem::tools::read_csv;
using lbdem::tools::select_window;

TEST_CASE("the jet mill study's window takes a run's first row from 0.07 s and its last row",
          "[scenarios]") {
  const std::string dir = std::string(LBDEM_SOURCE_DIR) + "/results/jet_mill/cg4_p5bar";
  const auto table = read_csv(dir + "/timeseries.csv");
  const std::vector<double>& t = table.column("time_s");
  REQUIRE(t.size() > 200);
  // What the study reads from the run's config: the feed's start and the row interval.
  const Config cfg = Config::from_file(dir + "/config.toml");
  const double spin_up = cfg.section("inflow").get("start", 0.0);
  const double interval = OutputSettings::from(cfg.section("run"), cfg.section("output")).interval;
  REQUIRE(spin_up == 0.03);
  const auto w = figure_window(spin_up, false, interval);
  const auto rows = select_window(t, w.from, w.to);
  // First row: the first at or after 0.1 s of run time (0.07 s of study time).
  REQUIRE(rows.size() > 2);
  REQUIRE(rows.begin > 0);
  CHECK(t[rows.begin] >= 0.1);
  CHECK(t[rows.begin - 1] < 0.1);
  // Last row: the run's last, written past 0.13 s.
  CHECK(rows.end == t.size());
  REQUIRE(t.back() > 0.13);
  // The window the tools were given before (no pad) dropped it: the test can fail.
  CHECK(select_window(t, w.from, 0.13).end == t.size() - 1);
}

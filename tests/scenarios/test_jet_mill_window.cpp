// The jet mill study's figure window (scenarios/jet_mill/jet_mill_study.hpp) on the rows a real
// run wrote: cg4_p5bar's timeseries.csv, kept in results/ (2026-11-25). The driver writes a row
// every whole number of exchange cycles (900 DEM steps of 0.5559 us for 5e-4 s: 0.50035 ms apart)
// and one at the run's last step, which it rounds up to a whole cycle (0.1300024 s for 0.13). The
// window's end row must be that last row, or the window totals lose a row interval (1.7 %).
#include <catch2/catch.hpp>

#include "scenarios/jet_mill/jet_mill_study.hpp"
#include "tools/src/run_folder.hpp"
#include "tools/src/window_stats.hpp"

using lbdem::scenarios::figure_window;
using lbdem::tools::read_csv;
using lbdem::tools::select_window;

TEST_CASE("the jet mill study's window takes a run's first row from 0.07 s and its last row",
          "[scenarios]") {
  const auto table =
      read_csv(std::string(LBDEM_SOURCE_DIR) + "/results/jet_mill/cg4_p5bar/timeseries.csv");
  const std::vector<double>& t = table.column("time_s");
  REQUIRE(t.size() > 200);
  const double spin_up = 0.03, row_interval = 5e-4;  // the preset's inflow.start, output.interval
  const auto w = figure_window(spin_up, false, row_interval);
  const auto rows = select_window(t, w.from, w.to);
  // First row: the first at or after 0.1 s of run time (0.07 s of study time).
  REQUIRE(rows.size() > 2);
  CHECK(t[rows.begin] >= 0.1);
  CHECK(t[rows.begin - 1] < 0.1);
  // Last row: the run's last, written just past 0.13 s.
  CHECK(rows.end == t.size());
  CHECK(t.back() > 0.13);
  // The window the tools were given before (no pad) dropped it: the test can fail.
  CHECK(select_window(t, w.from, figure_window(spin_up, false, 0).to).end == t.size() - 1);
  // The pad reaches half a row interval past the end, so in a run that went on it takes no row
  // beyond the one nearest the end.
  CHECK(w.to - 0.13 == Approx(0.5 * row_interval).epsilon(1e-9));
  const auto quick = figure_window(spin_up, true, 1e-4);
  CHECK(quick.from == Approx(0.032));
  CHECK(quick.to == Approx(0.034 + 0.5e-4));
}

// The jet mill study's figure window (studies/jet_mill_study.hpp) on the rows a real
// run wrote: cg4_p5bar's timeseries.csv and config.toml, kept in results/ (2026-11-25). Its driver
// wrote a row every 131 exchange cycles (655 DEM steps of 0.7639 us: 0.50035 ms apart) and one at
// its last step, 0.1300024 s for the end time 0.13 s. The window must end at that last row, or the
// window totals lose the last 0.41 ms (1.4 %). (A rerun of cg4_p5bar whose last step lands on
// 0.13 s exactly would leave nothing to drop: keep a run here whose last row lies past its end.)
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/config.hpp"
#include "helpers/cli.hpp"
#include "run/run_loop.hpp"
#include "studies/jet_mill_study.hpp"
#include "tools/src/run_folder.hpp"
#include "tools/src/window_stats.hpp"

using lbdem::Config;
using lbdem::run::OutputSettings;
using lbdem::studies::figure_window;
using lbdem::tools::read_csv;
using lbdem::tools::select_window;

TEST_CASE("the jet mill study's window takes a run's first row from 0.07 s and its last row",
          "[studies]") {
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

// `study jet_mill --no-run` on a folder of kept small outputs (no particles.h5, no snapshots):
// cg4_p5bar as results/ keeps it. Its mill_*.csv maps are the only copy: they must survive, and
// the table takes its speeds from them when they cover the window, else leaves them empty.
TEST_CASE("the jet mill study rebuilds its table from kept outputs without removing their maps",
          "[studies]") {
  namespace fs = std::filesystem;
  const std::string src = std::string(LBDEM_SOURCE_DIR) + "/results/jet_mill/cg4_p5bar";
  const std::string root = lbdem::test::tmpdir("mill_kept"), dir = root + "/cg4_p5bar";
  fs::create_directories(root);
  fs::copy(src, dir, fs::copy_options::recursive);
  REQUIRE(!fs::exists(dir + "/particles.h5"));
  const auto kept = read_csv(dir + "/mill_summary.csv");
  const double speed = kept.column("mean_speed_m_per_s").at(0);
  const auto study = [&] {
    return lbdem::test::cli("study jet_mill --no-run --cases cg4_p5bar --out " + root);
  };
  auto r = study();
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("maps of the same window are kept") != std::string::npos);
  CHECK(fs::exists(dir + "/mill_speed_map.csv"));
  const auto table = read_csv(root + "/study.csv");
  CHECK(table.column("mean_speed_m_per_s").at(0) == Approx(speed).epsilon(1e-3));  // 4 digits
  // The collision figures come from timeseries.csv and collisions.h5 (kept): present.
  CHECK(table.column("freq_pp_per_original_per_s").at(0) > 0);

  // Maps of another window (the summary's first snapshot moved 10 ms early): kept, not used.
  std::string text = lbdem::test::read_text(dir + "/mill_summary.csv");
  const auto at = text.find(",0.100069444,");
  REQUIRE(at != std::string::npos);
  text.replace(at, 13, ",0.090069444,");
  std::ofstream(dir + "/mill_summary.csv") << text;
  r = study();
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("no mill_*.csv maps of this window") != std::string::npos);
  CHECK(fs::exists(dir + "/mill_speed_map.csv"));
  CHECK(lbdem::test::read_text(dir + "/mill_summary.csv") == text);
  CHECK(std::isnan(read_csv(root + "/study.csv").column("mean_speed_m_per_s").at(0)));
  fs::remove_all(root);
}

// tools/jet_mill_figures.py leaves a --no-maps case's maps unread: the study names there the
// kept folders whose maps are of another window. The test gives such a case maps that cannot be
// read (a word where numbers belong): the script fails on them when it reads them, and succeeds
// only if it does not. The other case is cg4_p5bar's kept outputs, drawn as usual.
TEST_CASE("the jet mill figures leave out the maps of a case named by --no-maps",
          "[studies][tools][slow]") {
  namespace fs = std::filesystem;
  const std::string python = LBDEM_PYTHON;
  if (python.empty()) {
    WARN("no python3 with numpy/h5py/matplotlib was found at configure time: no figures to test");
    return;
  }
  const std::string src = std::string(LBDEM_SOURCE_DIR) + "/results/jet_mill/cg4_p5bar";
  const std::string root = lbdem::test::tmpdir("mill_figures");
  fs::create_directories(root);
  fs::copy(src, root + "/kept", fs::copy_options::recursive);
  fs::copy(src, root + "/stale", fs::copy_options::recursive);
  for (const char* m : {"positions", "speed_map", "wall_profile", "gas_profile", "gas_midplane",
                        "gas_radial_flow"}) {
    const std::string f = root + "/stale/mill_" + m + ".csv";
    fs::remove(f + ".gz");
    std::ofstream(f, std::ios::trunc) << "x_m,y_m,radius_m,speed_m_per_s\nnope,nope,nope,nope\n";
  }
  const std::string err = root + "/stderr.txt";
  const auto q = [](const std::string& s) { return "'" + s + "'"; };
  const auto figures = [&](const std::string& extra) {
    const std::string cmd = q(python) + " " +
                            q(std::string(LBDEM_SOURCE_DIR) + "/tools/jet_mill_figures.py") + " " +
                            q(root) + " --from 0.1 --to 0.13 --offset 0.03" + extra +
                            " kept stale > /dev/null 2> " + q(err);
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  };
  CHECK(figures(" --no-maps stale") == 0);
  for (const char* png :
       {"positions", "speed_map", "gas_midplane", "gas_profiles", "kinetic_energy", "wall_profile"})
    CHECK(fs::exists(root + "/" + png + ".png"));
  CHECK(figures("") != 0);                // the unreadable maps, read: the test can fail
  CHECK(figures(" --no-maps cg1") == 2);  // not one of the cases, and said so:
  CHECK(lbdem::test::read_text(err).find("--no-maps cg1: not one of the cases") !=
        std::string::npos);
  fs::remove_all(root);
}

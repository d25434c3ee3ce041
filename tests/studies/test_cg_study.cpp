// The coarse-graining study of any config (studies/cg_study.hpp): its verdicts on constructed
// differences, and the whole chain on a small box at size factors 1 and 2, which must hold the
// same mass of powder at both (its statistics are lbdem-compare-runs', tested in tests/tools).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "helpers/cli.hpp"
#include "scenarios/run_command.hpp"
#include "studies/cg_study.hpp"
#include "tools/src/run_folder.hpp"

using namespace lbdem;
using namespace lbdem::studies;
namespace fs = std::filesystem;

TEST_CASE("cg study verdicts: same within two combined errors, close within the tolerance",
          "[studies]") {
  // 1.05 +- 0.03 against 1.00 +- 0.04: combined error 0.05, z = 1.
  CgDifference d = cg_difference(1.05, 0.03, 1.0, 0.04, 0.05);
  CHECK(d.diff == Approx(0.05));
  CHECK(d.rel == Approx(0.05));
  CHECK(d.z == Approx(1.0));
  CHECK(d.verdict == "same");
  // z = 1.5 against a reference without error.
  CHECK(cg_difference(1.015, 0.01, 1.0, 0.0, 0.05).verdict == "same");
  // z = 3, 3 % off: resolved but within 5 %.
  d = cg_difference(1.03, 0.01, 1.0, 0.0, 0.05);
  CHECK(d.z == Approx(3.0));
  CHECK(d.verdict == "close");
  // z = 10, 10 % off.
  CHECK(cg_difference(1.10, 0.01, 1.0, 0.0, 0.05).verdict == "differs");
  // Below the reference counts the same way.
  CHECK(cg_difference(0.90, 0.01, 1.0, 0.0, 0.05).rel == Approx(-0.10));
  CHECK(cg_difference(0.90, 0.01, 1.0, 0.0, 0.05).verdict == "differs");
  // No errors (too few samples): no verdict.
  CHECK(cg_difference(1.1, std::nan(""), 1.0, 0.0, 0.05).verdict.empty());
  CHECK(cg_case_name(1) == "cg1");
  CHECK(cg_case_name(1.5) == "cg1_5");
  CHECK(cg_case_name(2) == "cg2");
}

namespace {

// The default box preset with its 3,000 beads given as their mass, 0.05 kg (588 beads at l = 1,
// 73 parcels at l = 2), for 0.3 s: the powder falls and settles in about 0.25 s.
std::string small_box(const std::string& dir) {
  fs::create_directories(dir);
  std::ifstream in(std::string(LBDEM_SOURCE_DIR) + "/scenarios/box/presets/default.toml");
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("count = 3000", 0) == 0) line = "mass = 0.05";
    if (line.rfind("end_time = ", 0) == 0) line = "end_time = 0.3";
    text += line + "\n";
  }
  const std::string path = dir + "/box.toml";
  std::ofstream(path) << text;
  return path;
}

std::vector<std::vector<std::string>> csv_rows(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream f(path);
  for (std::string line; std::getline(f, line);) {
    std::vector<std::string> cells;
    std::string cell;
    for (char c : line + ",") {
      if (c == ',') {
        cells.push_back(cell);
        cell.clear();
      } else {
        cell += c;
      }
    }
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace

TEST_CASE(
    "cg study: a box at size factors 1 and 2 holds the same powder, and each observable "
    "is compared with the finest level",
    "[studies]") {
  const std::string tmp = test::tmpdir("cg_study");
  const std::string cfg = small_box(tmp);
  const std::string out = tmp + "/study";
  const auto r =
      test::cli("study cg --config " + cfg + " --levels 1,2 --rule hertz --threads 1 --out " + out +
                " --observables potential_energy_J,kinetic_energy_J" +
                " --level-set 2:output.snapshot_interval=0.1");
  REQUIRE(r.code == 0);
  // The level override reached level 2's run only.
  CHECK(
      Config::from_file(out + "/cg2/config.toml").section("output").get("snapshot_interval", 0.0) ==
      0.1);
  CHECK(
      Config::from_file(out + "/cg1/config.toml").section("output").get("snapshot_interval", 0.0) ==
      0.05);
  // The same system at each level: the fill's 0.05 kg, to within the last parcel the fill placed
  // (at most the largest parcel, r = 2.2 mm x l, beyond the mass asked).
  for (const double l : {1.0, 2.0}) {
    const auto run = tools::RunFolder::open(out + "/" + cg_case_name(l));
    const double m = tools::snapshot_mass(run, 0.0);
    const double r_max = 2.2e-3 * l;
    CHECK(m >= 0.05);
    CHECK(m <= 0.05 + 2500 * 4.0 / 3.0 * M_PI * r_max * r_max * r_max);
    CHECK(run.size_factor == l);
  }
  // The columns a study checks its observables against are the ones the run wrote.
  Config c = Config::from_file(cfg);
  c.set_override("coarse_grain.size_factor=2");
  c.set_override("coarse_grain.rule=hertz");
  CHECK(scenarios::read_as_scenario("box", c) ==
        tools::read_csv(out + "/cg2/timeseries.csv").names);
  // One row per level, the finest as the reference (no verdict), the other judged.
  const auto levels = csv_rows(out + "/cg_levels.csv");
  REQUIRE(levels.size() == 3);
  CHECK(levels[1][0] == "cg1");
  CHECK(levels[2][0] == "cg2");
  const auto obs = csv_rows(out + "/cg_observables.csv");
  REQUIRE(obs.size() == 5);
  const auto& head = obs[0];
  const auto col = [&](const char* name) {
    return std::size_t(std::find(head.begin(), head.end(), name) - head.begin());
  };
  REQUIRE(col("mean_verdict") < head.size());
  for (std::size_t k = 1; k < obs.size(); ++k) {
    const auto& row = obs[k];
    // Rows every 0.005 s over 0.15-0.3 s: 31, or one fewer where the run's last row (at its end
    // step, off the row grid) made the comparison resample at the median spacing.
    const int samples = std::stoi(row[col("samples")]);
    CHECK(samples >= 30);
    CHECK(samples <= 31);
    if (row[col("case")] == "cg1") {
      CHECK(row[col("mean_verdict")].empty());
    } else {
      const std::string v = row[col("mean_verdict")];
      CHECK((v == "same" || v == "close" || v == "differs"));
    }
  }
  CHECK(fs::exists(out + "/cg_report.txt"));
  // Each observable's series of both levels, as lbdem-compare-runs writes them for its figure.
  const auto series = tools::read_csv(out + "/potential_energy_J_stats.csv", true);
  REQUIRE(series.rows() == 2);
  CHECK(series.cell("label", 0) == "cg1");
  CHECK(series.cell("label", 1) == "cg2");
  CHECK(fs::exists(out + "/kinetic_energy_J_spectra.csv"));
  // Another config into the same folder is refused, naming the key its levels' runs differ in,
  // before anything is run or written.
  {
    std::ifstream in(cfg);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("mass = 0.05"), 11, "mass = 0.06");
    std::ofstream(tmp + "/other.toml") << text;
  }
  const auto stamp = fs::last_write_time(out + "/cg_levels.csv");
  const auto other =
      test::cli("study cg --config " + tmp + "/other.toml --levels 1,2 --rule hertz" +
                " --threads 1 --out " + out);
  CHECK(other.code == 2);
  CHECK(other.err.find("is a run of another config (fill[0].mass") != std::string::npos);
  CHECK(fs::last_write_time(out + "/cg_levels.csv") == stamp);
  fs::remove_all(tmp);
}

TEST_CASE("cg study: bad input names the option, exits 2 and writes nothing", "[studies]") {
  const std::string tmp = test::tmpdir("cg_study_bad");
  const std::string cfg = small_box(tmp);
  const std::string out = tmp + "/study";
  const std::string box = std::string(LBDEM_SOURCE_DIR) + "/scenarios/box/presets/default.toml";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"study cg --levels 1,2", "'--config'"},
      {"study cg --config " + tmp + "/none.toml --levels 1,2", "'--config'"},
      {"study cg --config " + cfg + " --levels 2", "'--levels'"},
      {"study cg --config " + cfg + " --levels 1,0.5", "'--levels'"},
      {"study cg --config " + cfg + " --levels 1,2,2", "'--levels'"},
      {"study cg --config " + cfg + " --levels 1,2 --set coarse_grain.size_factor=3", "'--set'"},
      {"study cg --config " + cfg + " --levels 1,2 --level-set 3:dem.skin=1e-4", "names no level"},
      {"study cg --config " + cfg + " --levels 1,2 --level-set dem.skin=1e-4", "L:key=value"},
      {"study cg --config " + cfg + " --levels 1,2 --level-set 2:coarse_grain.rule=hertz",
       "'--level-set'"},
      {"study cg --config " + cfg + " --levels 1,2 --set dem.skin=1e-4 --level-set 2:dem.skin=2e-4",
       "which --set dem.skin=1e-4 sets too"},
      {"study cg --config " + box + " --levels 1,2", "'fill[0].count'"},
      {"study cg --config " + cfg + " --levels 1,2 --rule hertz --observables kinetic_energy",
       "did you mean 'kinetic_energy_J'"},
      {"study cg --config " + cfg + " --levels 1,2 --rule linear_similarity", "(at level l = 2)"},
      {"study rheometer --levels 1,2", "'--levels'"},
  };
  for (const auto& [args, expected] : cases) {
    INFO(args);
    const auto r = test::cli(args + " --out " + out);
    CHECK(r.code == 2);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
  }
  fs::remove_all(tmp);
}

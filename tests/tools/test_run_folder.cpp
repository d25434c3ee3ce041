// Reading run folders: a CSV being appended to, the error for an unknown column, the window error.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tools/src/run_folder.hpp"

using namespace lbdem::tools;
namespace fs = std::filesystem;

namespace {
fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("lbdem_test_tools_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST_CASE("timeseries.csv: short rows and a partial last line are dropped", "[tools]") {
  const fs::path d = fresh_dir("csv");
  std::ofstream(d / "timeseries.csv") << "time_s,torque_Nm\n0,1.5\n0.1,2\n0.2\n0.3,nan\n0.4,7";
  std::ofstream(d / "config.toml") << "[coarse_grain]\nsize_factor = 1.6\n";
  const RunFolder r = RunFolder::open(d.string());
  REQUIRE(r.series.rows() == 3);  // 0.2 has one field; 0.4 has no newline yet
  CHECK(r.time()[2] == 0.3);
  CHECK(std::isnan(r.series.column("torque_Nm")[2]));
  CHECK(r.size_factor == 1.6);
  try {
    r.series.column("torqe_Nm");
    FAIL("no error for an unknown column");
  } catch (const ToolError& e) {
    CHECK(std::string(e.what()).find("known: time_s, torque_Nm") != std::string::npos);
  }
  CHECK(window_error(r, 5, 6, 0, 2).find("it covers [0, 0.3] s") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("CSV text cells: quoted commas and quotes read back as written", "[tools]") {
  const fs::path d = fresh_dir("csv_text");
  const std::vector<std::string> texts = {"plain", "a, b", "the \"top\" of the bed", "", "-"};
  {
    std::ofstream f(d / "t.csv");
    f << "label,value\n";
    for (const auto& t : texts) f << csv_field(t) << ",1.5\n";
  }
  const Table t = read_csv((d / "t.csv").string(), true);
  REQUIRE(t.rows() == texts.size());
  for (std::size_t r = 0; r < texts.size(); ++r) {
    CHECK(t.cell("label", r) == texts[r]);
    CHECK(t.number("value", r) == 1.5);
  }
  CHECK(csv_field("a, b") == "\"a, b\"");
  CHECK(csv_field("x\"y") == "\"x\"\"y\"");
  fs::remove_all(d);
}

TEST_CASE("Missing folder or series is a ToolError", "[tools]") {
  const fs::path d = fresh_dir("missing");
  CHECK_THROWS_AS(RunFolder::open((d / "nope").string()), ToolError);
  CHECK_THROWS_AS(RunFolder::open(d.string()), ToolError);  // no timeseries.csv
  fs::remove_all(d);
}

// The inflow ledger as the powder mass of a folder without snapshots: inserted less removed at
// the last row at or before t, for a run that starts empty. Exact: one subtraction of the
// numbers in the file (the values are chosen so that it is exact in binary too).
TEST_CASE("ledger_mass: inserted less removed for a run that starts empty, else NaN", "[tools]") {
  const fs::path d = fresh_dir("ledger");
  const auto open = [&](const std::string& rows) {
    std::ofstream(d / "timeseries.csv", std::ios::trunc)
        << "time_s,particles,mass_removed_kg,mass_inserted_kg\n"
        << rows;
    return RunFolder::open(d.string());
  };
  const RunFolder fed = open("0,0,0,0\n0.5,10,0,0.5\n1,12,0.25,1\n");
  CHECK(ledger_mass(fed, 1) == 0.75);
  CHECK(ledger_mass(fed, 0.9) == 0.5);      // the row at 0.5 s, not the next one
  CHECK(std::isnan(ledger_mass(fed, 0)));   // nothing in yet: no mass to divide by
  CHECK(std::isnan(ledger_mass(fed, -1)));  // before the first row
  // Particles at the start came from a fill, which the ledger does not count.
  CHECK(std::isnan(ledger_mass(open("0,5,0,0\n1,12,0.25,1\n"), 1)));
  std::ofstream(d / "timeseries.csv", std::ios::trunc) << "time_s,particles\n0,0\n1,3\n";
  CHECK(std::isnan(ledger_mass(RunFolder::open(d.string()), 1)));  // no inflow columns
  fs::remove_all(d);
}

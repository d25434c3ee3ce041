// The run manifest (run/run_manifest.hpp, run.toml): what a run tells studies and
// tools in machine-readable form must be what its log and its checkpoint say, and a study's cost
// columns must come from it.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "core/h5.hpp"
#include "helpers/cli.hpp"
#include "run/run_cost.hpp"
#include "run/run_manifest.hpp"
#include "studies/study_case.hpp"

using namespace lbdem;
using namespace lbdem::run;
using namespace lbdem::studies;
namespace fs = std::filesystem;

TEST_CASE("run manifest: written and read back exactly", "[scenarios]") {
  const std::string dir = test::tmpdir("manifest_roundtrip");
  fs::create_directories(dir);
  RunManifest m;
  m.scenario = "box";
  m.version = "0.1.0";
  m.config_hash = -1234567890123456789;
  m.time_s = 0.1 + 0.2;  // not a short decimal: the text must carry all 17 digits
  m.end_time_s = 1.0 / 3.0;
  m.complete = true;
  m.derived = {{"particles", 150, ""},
               {"time step dt", 1.0 / 7e5, "s"},
               {"time step dt", 2.0, "s"},  // a repeated name: the first row is kept
               {"Dp / (rho c_s^2)", -0.0, ""}};
  m.cost = RunCost{0.0, 0.06, 12.5, {{"DEM: kick and drift", 1.0 / 3}, {"output", 0.25}}};
  write_run_manifest(dir, m);
  const auto r = read_run_manifest(dir);
  REQUIRE(r);
  CHECK(r->scenario == "box");
  CHECK(r->version == "0.1.0");
  CHECK(r->config_hash == m.config_hash);
  CHECK(r->time_s == m.time_s);
  CHECK(r->end_time_s == m.end_time_s);
  CHECK(r->complete);
  CHECK(r->number("particles") == 150);
  CHECK(r->number("time step dt") == 1.0 / 7e5);
  CHECK(r->number("Dp / (rho c_s^2)") == 0.0);
  CHECK(std::isnan(r->number("no such row")));
  REQUIRE(r->cost);
  CHECK(r->cost->wall_s == 12.5);
  CHECK(r->cost->to_s == 0.06);
  REQUIRE(r->cost->phases.size() == 2);
  CHECK(r->cost->phases[0].second == 1.0 / 3);
  CHECK(!read_run_manifest(dir + "/none"));
  fs::remove_all(dir);
}

TEST_CASE("run manifest: a run's manifest holds its banner's numbers and its checkpoint's sums",
          "[scenarios]") {
  const std::string dir = test::tmpdir("manifest_run");
  REQUIRE(test::cli("run box --threads 1 --out " + dir + test::beads_near_floor(150) +
                    " --set run.end_time=0.02 --set output.checkpoint_interval=0.01")
              .code == 0);
  const auto m = read_run_manifest(dir);
  REQUIRE(m);
  CHECK(m->scenario == "box");
  CHECK(m->complete);
  // The numbers as the log printed them (%.6g there: to that precision).
  const std::string log = dir + "/log.txt";
  for (const char* key : {"particles", "time step dt"}) {
    CAPTURE(key);
    CHECK(m->number(key) == Approx(banner_number(log, key)).epsilon(1e-5));
  }
  const H5In f(dir + "/checkpoint.h5");
  CHECK(m->number("particles") == double(f.doubles("/dem/radius").size()));
  CHECK(m->config_hash == f.attr_int("config_hash", "/run"));
  // The cost sums are the checkpoint's, and the study's cost per simulated second is read from
  // them.
  const auto c = read_run_cost(dir + "/checkpoint.h5");
  REQUIRE(c);
  REQUIRE(m->cost);
  CHECK(m->cost->wall_s == c->wall_s);
  CHECK(m->cost->to_s == c->to_s);
  CHECK(m->time_s == c->to_s);                   // the step that reached run.end_time = 0.02 s
  using Phases = std::map<std::string, double>;  // the manifest lists them by name
  CHECK(Phases(m->cost->phases.begin(), m->cost->phases.end()) ==
        Phases(c->phases.begin(), c->phases.end()));
  const PartCosts p = part_costs(dir);
  CHECK(p.total == c->wall_s / (c->to_s - c->from_s));
  CHECK(p.split);
  fs::remove_all(dir);
}

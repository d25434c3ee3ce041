// run::RunLoop and its observers (run/observer.hpp): the loop calls each observer at its points, in
// the order given: its columns after the loop's own with one value per row, before_step once per
// DEM step, its state into every checkpoint and back on resume (so that the resumed series equals
// an uninterrupted one), every observer's snapshot data sets to each snapshot, and a health
// message stops the run as diverged, keeping the last output.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/h5.hpp"
#include "core/log.hpp"
#include "helpers/dem_setup.hpp"
#include "lbm/lbm_solver.hpp"
#include "run/run_loop.hpp"

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

// Counts the DEM steps it was called before, and records what the loop handed it.
struct StepCounter : run::Observer {
  explicit StepCounter(std::string n, std::vector<std::string>* calls = nullptr)
      : name(std::move(n)), order(calls) {}
  std::string name;
  std::vector<std::string>* order;
  double steps = 0;
  double stop_at = std::numeric_limits<double>::infinity();
  std::size_t arrays_seen = 0, snapshots = 0;

  std::vector<std::string> row_columns() const override { return {name + "_steps"}; }
  void on_row(const run::Instant& /*now*/, std::vector<double>& row) const override {
    row.push_back(steps);
  }
  void before_step(const run::Instant& /*now*/) override {
    steps += 1;
    if (order && order->size() < 4) order->push_back(name);
  }
  void on_checkpoint(H5Out& f) const override { f.attr(name + "_steps", steps); }
  void on_resume(const H5In& f) override { steps = f.attr_double(name + "_steps"); }
  std::vector<run::SnapshotArray> snapshot_arrays() const override {
    return {{name + "_array", {steps}}};
  }
  void on_snapshot(const std::string& /*dir*/, const std::vector<double>& times,
                   const std::vector<run::SnapshotArray>& arrays) override {
    arrays_seen = arrays.size();
    snapshots = times.size();
  }
  std::optional<std::string> health(const run::Instant& now) override {
    if (now.time_s >= stop_at) return name + " objects at t = " + std::to_string(now.time_s);
    return std::nullopt;
  }
};

constexpr double kDt = 1e-5;

// Three beads dropping onto a floor: contacts, so the DEM's own columns move too.
std::unique_ptr<dem::DemSolver> beads() {
  auto s = std::make_unique<dem::DemSolver>(test::settings(kDt, Vec3(0, 0, -9.81)),
                                            std::vector<dem::Material>{test::glass()});
  s->add_wall(test::floor_wall(-0.0006));
  for (int k = 0; k < 3; ++k)
    s->add_particle(Vec3(0.002 * k, 0, 0.0001 * k), Vec3::Zero(), 5e-4, 0);
  return s;
}

run::OutputSettings output(double end) {
  run::OutputSettings o;
  o.end_time = end;
  o.interval = 0.002;
  o.snapshot_interval = 0.005;
  o.checkpoint_interval = 0.004;
  return o;
}

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("lbdem_test_run_loop_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

// Runs the beads to `end` in `dir` with observers a and b (resuming if asked); returns the loop's
// exit code.
// Runs `loop` quietly in `dir`, from its checkpoint if `resume`; returns its exit code.
int run_in(run::RunLoop& loop, const std::string& dir, bool resume) {
  Log log;
  log.set_quiet(true);
  run::RunContext ctx;
  ctx.dir = dir;
  ctx.resume = resume;
  ctx.log = &log;
  return loop.run(ctx);
}

int run_beads(const std::string& dir, double end, bool resume, StepCounter& a, StepCounter& b) {
  auto s = beads();
  run::RunParts parts;
  parts.observers = {&a, &b};
  run::RunLoop loop(*s, output(end), std::move(parts));
  return run_in(loop, dir, resume);
}

// A periodic 4^3 gas driven by a body force, alone: its steps are the run's clock. `ramp_times`
// collects the start time of every gas step.
std::unique_ptr<run::CoupledGas> lone_gas(std::vector<double>* ramp_times) {
  lbm::LbmSettings s;
  s.nx = s.ny = s.nz = 4;
  s.collision = lbm::Bgk::from_tau(0.8);
  s.body_force = Vec3(1e-6, 0, 0);
  auto g = std::make_unique<lbm::LbmSolver>(s);
  g->initialize([](int, int, int, double& rho, Vec3& u) { rho = 1, u = Vec3::Zero(); });
  return std::make_unique<run::CoupledGas>(std::move(g), run::conform_dem_step(kDt, kDt), kDt,
                                           [ramp_times](double t) {
                                             if (ramp_times) ramp_times->push_back(t);
                                           });
}

int run_gas(const std::string& dir, double end, bool resume, StepCounter& a,
            std::vector<double>* ramp_times = nullptr) {
  auto gas = lone_gas(ramp_times);
  run::RunParts parts;
  parts.observers = {&a};
  parts.gas = gas.get();
  run::RunLoop loop(output(end), std::move(parts));
  return run_in(loop, dir, resume);
}

}  // namespace

TEST_CASE("run loop: observers' columns, rows, steps and snapshot data sets, in the given order",
          "[run]") {
  const std::string dir = fresh_dir("order");
  std::vector<std::string> calls;
  StepCounter a("a", &calls), b("b", &calls);
  REQUIRE(run_beads(dir, 0.01, false, a, b) == 0);
  CHECK(calls == std::vector<std::string>{"a", "b", "a", "b"});
  CHECK(a.steps == 1000);  // once per DEM step: 0.01 s of 1e-5 s
  CHECK(b.steps == 1000);
  // Snapshots at 0, 0.005 and 0.01 s, each handed both observers' data sets.
  CHECK(a.snapshots == 3);
  CHECK(a.arrays_seen == 2);
  CHECK(b.arrays_seen == 2);

  const std::string csv = read_text(dir + "/timeseries.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  std::string loop_header;
  for (const auto& c : run::loop_columns()) loop_header += (loop_header.empty() ? "" : ",") + c;
  CHECK(header == loop_header + ",a_steps,b_steps");
  // The last row (t = 0.01 s) ends with both counts: the step count at that row.
  const std::string body = csv.substr(0, csv.size() - 1);
  const std::string last = body.substr(body.rfind('\n') + 1);
  CHECK(last.substr(last.size() - 10) == ",1000,1000");
  fs::remove_all(dir);
}

TEST_CASE(
    "run loop: an observer's state goes into the checkpoint and back, so a resume equals a "
    "run that never stopped",
    "[run]") {
  const std::string whole = fresh_dir("whole"), parts = fresh_dir("parts");
  StepCounter a("a"), b("b");
  REQUIRE(run_beads(whole, 0.01, false, a, b) == 0);
  StepCounter a1("a"), b1("b");
  REQUIRE(run_beads(parts, 0.006, false, a1, b1) == 0);
  StepCounter a2("a"), b2("b");  // fresh observers: their counts come from the checkpoint
  REQUIRE(run_beads(parts, 0.01, true, a2, b2) == 0);
  CHECK(a2.steps == 1000);
  CHECK(read_text(parts + "/timeseries.csv") == read_text(whole + "/timeseries.csv"));
  fs::remove_all(whole);
  fs::remove_all(parts);
}

TEST_CASE("run loop: an observer's health message stops the run as diverged, the last output kept",
          "[run]") {
  const std::string dir = fresh_dir("health");
  StepCounter a("a"), b("b");
  b.stop_at = 0.0055;  // checked at outputs: the row at 0.006 s finds it
  try {
    run_beads(dir, 0.01, false, a, b);
    FAIL("no Diverged for an observer's health message");
  } catch (const run::Diverged& e) {
    CHECK(std::string(e.what()).find("b objects at t = 0.006") != std::string::npos);
  }
  // Rows up to 0.004 s and the checkpoint of 0.004 s; nothing of the state that failed.
  const std::string csv = read_text(dir + "/timeseries.csv");
  const std::string body = csv.substr(0, csv.size() - 1);
  const std::string last = body.substr(body.rfind('\n') + 1);
  CHECK(std::stod(last.substr(0, last.find(','))) == Approx(0.004).margin(1e-9));
  CHECK(H5In(dir + "/checkpoint.h5").attr_double("time_s", "/dem") == Approx(0.004).margin(1e-9));
  fs::remove_all(dir);
}

TEST_CASE(
    "run loop: a run without particles is clocked by its gas, writes no particle files, and "
    "resumes to the same gas",
    "[run]") {
  const std::string whole = fresh_dir("gas_whole"), parts = fresh_dir("gas_parts");
  StepCounter a("a");
  std::vector<double> ramp_times;
  REQUIRE(run_gas(whole, 0.01, false, a, &ramp_times) == 0);
  CHECK(a.steps == 1000);  // once per gas step: 0.01 s of 1e-5 s
  REQUIRE(ramp_times.size() == 1000);
  CHECK(ramp_times[999] == Approx(999 * kDt).margin(1e-15));  // the step's start time
  CHECK(a.snapshots == 3);                                    // at 0, 0.005 and 0.01 s
  const std::string csv = read_text(whole + "/timeseries.csv");
  CHECK(csv.substr(0, csv.find('\n')) == "time_s,a_steps");
  for (const char* file : {"particles.h5", "particles.xdmf", "collisions.h5"})
    CHECK_FALSE(fs::exists(whole + "/" + file));
  {
    const H5In f(whole + "/checkpoint.h5");
    CHECK_FALSE(f.has("/dem"));
    CHECK(f.attr_double("time_s") == Approx(0.01).margin(1e-12));
    CHECK(f.attr_int("steps", "/fluid") == 1000);
  }
  StepCounter a1("a"), a2("a");
  REQUIRE(run_gas(parts, 0.006, false, a1) == 0);
  REQUIRE(run_gas(parts, 0.01, true, a2) == 0);
  CHECK(a2.steps == 1000);
  CHECK(read_text(parts + "/timeseries.csv") == csv);
  CHECK(H5In(parts + "/checkpoint.h5").doubles("/fluid/populations") ==
        H5In(whole + "/checkpoint.h5").doubles("/fluid/populations"));
  fs::remove_all(whole);
  fs::remove_all(parts);

  // Without a gas, or with one coupled to particles, there is no clock.
  CHECK_THROWS_AS(run::RunLoop(output(0.01), run::RunParts{}), std::invalid_argument);
}

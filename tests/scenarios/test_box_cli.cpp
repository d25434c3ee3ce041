// The box scenario through the real executable: input errors (exit 2, key named, no run folder),
// and checkpoint/resume equal to an uninterrupted run, bitwise.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <unistd.h>

#include "core/h5.hpp"
#include "helpers/cli.hpp"
#include "helpers/resume_check.hpp"
#include "run/run_cost.hpp"

namespace fs = std::filesystem;

namespace {
using lbdem::test::cli;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

// A short, small version of the default preset.
// The beads start near the floor, so the checkpoint falls in the middle of collisions and carries
// contact history.
const std::string kSmall = lbdem::test::beads_near_floor(150) +
                           " --set run.end_time=0.06 --set output.checkpoint_interval=0.03";
}  // namespace

TEST_CASE("bad input exits with 2, names the key and leaves no run folder", "[scenarios][input]") {
  struct Case {
    std::string set, key;
  } cases[] = {
      {"dem.dtt=1e-6", "dem.dtt"},                         // unknown key
      {"fill[0].radius.min=-1e-3", "fill[0].radius.min"},  // negative size
      {"dem.dt=1e-3", "dem.dt"},                           // unstable time step
      {"contact.normal=\"herz\"", "contact.normal"},       // unknown law
      {"particle=[{position=[1.0,0.0,0.0],radius=1e-3}]",
       "particle[0].position"},                      // outside the box
      {"fill[0].hi=[0.06,0.06,0.5]", "fill[0].hi"},  // the corner that is out, not lo
      // --set paths that cannot be placed name the part in the way:
      {"fill[3].count=10", "fill"},                          // past the array's one entry
      {"fill[0].radius.kind.x=1", "fill[0].radius.kind"},    // through a value
      {"box.lo.x=1", "box.lo"},                              // through an array of numbers
      {"run[0].seed=1", "run"},                              // indexing a table
      {"fill[x].count=1", "--set"},                          // an index that is no number
      {".=1", "--set"},                                      // no key at all
      {"materials[0].densty=900", "materials[0].densty"},    // unknown, in an entry
      {"fill[0].radius.sigma=0.1", "fill[0].radius.sigma"},  // read for lognormal fills only
  };
  for (const auto& c : cases) {
    const std::string out = tmpdir("bad");
    const auto r = cli("run box --out " + out + " --set '" + c.set + "'");
    INFO(c.set << " -> " << r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("'" + c.key + "'") != std::string::npos);
    CHECK(r.err.find("fix:") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line
    CHECK_FALSE(fs::exists(out));
  }
  // A thread count below 1: lbdem's one line, not CLI11's two without a fix.
  const std::string t0_out = tmpdir("bad");
  const auto t0 = cli("run box --threads 0 --out " + t0_out);
  CHECK(t0.code == 2);
  CHECK_FALSE(fs::exists(t0_out));
  CHECK(t0.err.find("'--threads' = 0") != std::string::npos);
  CHECK(std::count(t0.err.begin(), t0.err.end(), '\n') == 1);
  // A size factor that is not finite stops at the reader, with coarse graining's own fix.
  CHECK(cli("run box --set coarse_grain.size_factor=nan").err.find("give a size factor l >= 1") !=
        std::string::npos);
  // --resume of a folder that is not there, or of a file: said so, and nothing written.
  const std::string missing = tmpdir("no_such_run"), file = tmpdir("resume_file");
  std::ofstream(file) << "not a run folder\n";
  for (const std::string& bad : {missing, file}) {
    const auto r = cli("run --resume " + bad);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("'--resume' = " + bad) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  CHECK(cli("run --resume " + file).err.find("is a file") != std::string::npos);
  fs::remove(file);
  CHECK_FALSE(fs::exists(missing));
  // The nearest known key is suggested for a misspelt one.
  CHECK(cli("run box --set dem.dtt=1e-6").err.find("did you mean 'dem.dt'") != std::string::npos);
}

TEST_CASE("run --config FILE takes the scenario the file names", "[scenarios][input]") {
  const std::string preset = std::string(LBDEM_SOURCE_DIR) + "/scenarios/box/presets/default.toml";
  // Named by the file alone: the run starts (a tiny, short box).
  const std::string out = tmpdir("config_names_scenario");
  const auto ok =
      cli("run --config " + preset + " --out " + out + kSmall +
          " --set run.end_time=0.002 --set output.checkpoint_interval=0.002 --no-plots");
  INFO(ok.err);
  CHECK(ok.code == 0);
  CHECK(fs::exists(out + "/timeseries.csv"));
  fs::remove_all(out);
  // A file for another scenario than the command names, and a file that names none: one line
  // each, exit 2, nothing written.
  const std::string other = tmpdir("other_scenario"), bare = tmpdir("bare.toml");
  std::ofstream(bare) << "[run]\nend_time = 0.01\n";
  const auto clash = cli("run fluidized_bed --config " + preset + " --out " + other);
  const auto none = cli("run --config " + bare + " --out " + other);
  for (const auto& r : {clash, none}) {
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("'scenario'") != std::string::npos);
    CHECK(r.err.find("fix:") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  CHECK(clash.err.find("'fluidized_bed'") != std::string::npos);
  CHECK_FALSE(fs::exists(other));
  fs::remove(bare);
}

TEST_CASE("a resumed run equals an uninterrupted one bitwise", "[scenarios][checkpoint]") {
  const std::string full = tmpdir("full"), part = tmpdir("part");
  REQUIRE(cli("run box --out " + full + kSmall).code == 0);
  // Stop at the checkpoint at 0.03 s, then continue to 0.06 s.
  REQUIRE(cli("run box --out " + part + kSmall + " --set run.end_time=0.03").code == 0);
  const auto first = lbdem::run::read_run_cost(part + "/checkpoint.h5");
  REQUIRE(cli("run --resume " + part + " --set run.end_time=0.06").code == 0);
  // The cost sums (run_cost.hpp) go through the checkpoint: after the resume they still begin at
  // t = 0 (a resume that started them afresh would begin them at 0.03) and hold both invocations.
  const auto both = lbdem::run::read_run_cost(part + "/checkpoint.h5");
  REQUIRE(first);
  REQUIRE(both);
  // Each ends where its checkpoint's state stands (0.03 and 0.06 s rounded to whole steps).
  const double t_both = lbdem::H5In(part + "/checkpoint.h5").attr_double("time_s", "/dem");
  CHECK(first->from_s == 0);
  CHECK(first->to_s == Approx(0.03).margin(1e-4));
  CHECK(both->from_s == 0);
  CHECK(both->to_s == t_both);
  CHECK(both->to_s == Approx(0.06).margin(1e-4));
  CHECK(both->wall_s > first->wall_s);
  // Contacts exist in pairs_tally: the history really went through the checkpoint. The time series
  // continues without gaps or duplicates: same rows as the uninterrupted run.
  lbdem::test::check_same_runs(
      full, part, {"/dem/x", "/dem/v", "/dem/omega", "/dem/force", "/dem/pairs_tally"});
  // Physics cannot change on resume (the checkpoint would not match it): exit 2, key named.
  const auto bad = cli("run --resume " + part + " --set materials[0].friction=0.1");
  CHECK(bad.code == 2);
  CHECK(bad.err.find("materials[0].friction") != std::string::npos);
  fs::remove_all(full);
  fs::remove_all(part);
}

namespace {

// Runs lbdem-cli ARGS in the background and sends it SIGTERM after `seconds`: true when it then
// exited with 130 and left status "stopped".
bool terminated_after(const std::string& args, double seconds) {
  const std::string cmd = std::string(LBDEM_CLI) + " " + args +
                          " --no-plots > /dev/null 2>&1 & pid=$!; sleep " +
                          std::to_string(seconds) + "; kill -TERM $pid; wait $pid; exit $?";
  const int rc = std::system(cmd.c_str());  // /bin/sh: background job, signal, wait for its status
  const std::string dir = args.substr(args.find("--out ") + 6);
  const std::string status = read_text(dir.substr(0, dir.find(' ')) + "/status");
  INFO("exit " << (WIFEXITED(rc) ? WEXITSTATUS(rc) : -1) << ", status: " << status);
  return WIFEXITED(rc) && WEXITSTATUS(rc) == 130 && status.rfind("stopped", 0) == 0;
}

}  // namespace

TEST_CASE("SIGTERM writes a checkpoint and the resumed run equals an uninterrupted one",
          "[scenarios][checkpoint][slow]") {
  const std::string full = tmpdir("sig_full"), part = tmpdir("sig_part");
  // Long enough (about 2 s) that the signal after 0.5 s lands in the middle of the run.
  const std::string args = kSmall + " --set run.end_time=0.6 --set output.checkpoint_interval=0.6";
  REQUIRE(cli("run box --out " + full + args).code == 0);
  REQUIRE(terminated_after("run box --out " + part + args, 0.5));
  REQUIRE(cli("run --resume " + part).code == 0);
  lbdem::test::check_same_runs(full, part, {"/dem/x", "/dem/v", "/dem/omega"}, false);
  fs::remove_all(full);
  fs::remove_all(part);
}

TEST_CASE("a run suspended with SIGTSTP leaves the suspension out of its wall time and cost sums",
          "[scenarios][checkpoint][slow]") {
  const std::string dir = tmpdir("tstp");
  // About 2 s of stepping (0.8 s on a 2026 2-core VM for 0.6 s of simulated time), so that the
  // suspension after 0.5 s, for 1 s, lands inside the run, as a user frees the cores for a while.
  const std::string args = kSmall + " --set run.end_time=1.5 --set output.checkpoint_interval=1.5";
  const std::string cmd = std::string(LBDEM_CLI) + " run box --out " + dir + args +
                          " --no-plots > /dev/null 2>&1 & pid=$!; sleep 0.5; kill -TSTP $pid; "
                          "sleep 1; kill -CONT $pid; wait $pid; exit $?";
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = std::system(cmd.c_str());
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  REQUIRE(WIFEXITED(rc));
  REQUIRE(WEXITSTATUS(rc) == 0);
  const std::string log = read_text(dir + "/log.txt");
  std::smatch m;
  REQUIRE(std::regex_search(log, m, std::regex("suspended \\(SIGTSTP\\) for ([0-9.eE+-]+) s")));
  const double held = std::stod(m[1]);
  // The run stood stopped between the two kills, 1 s apart; 0.1 s allows for the shell and the
  // scheduler delivering the signals late.
  CHECK(held >= 0.9);
  CHECK(held < elapsed);
  const auto cost = lbdem::run::read_run_cost(dir + "/checkpoint.h5");
  REQUIRE(cost);
  // The stepping loop's sum lies inside the whole invocation less the suspension; counted, the
  // suspension (1 s) would exceed the set-up and output left out of the sum (tenths of a second)
  // and break this.
  CHECK(cost->wall_s > 0);
  CHECK(cost->wall_s + held <= elapsed);
  fs::remove_all(dir);
}

TEST_CASE("SIGTERM inside a long exchange interval stops between gas steps and resumes bitwise",
          "[scenarios][checkpoint][slow]") {
  // A small walled bed whose one exchange interval holds 30,000 gas steps (about 1.5 s of wall
  // time): before stops were taken between gas steps, a stop waited for the interval's end.
  const std::string full = tmpdir("gas_sig_full"), part = tmpdir("gas_sig_part");
  const std::string args =
      " --config " + std::string(LBDEM_SOURCE_DIR) +
      "/scenarios/fluidized_bed/presets/mueller_u09.toml --set 'box.hi=[0.02,0.01,0.04]' --set "
      "'fill[0].hi=[0.02,0.01,0.03]' --set 'bed.pressure_taps=[0.0,0.04]' --set "
      "fill[0].mass=1e-4 --set coupling.exchange_every=30000 --set run.end_time=0.001 --set "
      "output.checkpoint_interval=0.001";
  REQUIRE(cli("run fluidized_bed --out " + full + args).code == 0);
  REQUIRE(terminated_after("run fluidized_bed --out " + part + args, 0.5));
  {
    // The stop came inside the interval: the checkpoint holds the gas part-way and the interval's
    // state, the DEM at its start.
    const lbdem::H5In f(part + "/checkpoint.h5");
    REQUIRE(f.has("/coupling_interval"));
    const auto done = f.attr_int("steps_done", "/coupling_interval");
    CHECK(done > 0);
    CHECK(done < f.attr_int("steps", "/coupling_interval"));
    CHECK(f.attr_int("steps", "/fluid") == done);
  }
  REQUIRE(cli("run --resume " + part).code == 0);
  lbdem::test::check_same_runs(full, part,
                               {"/dem/x", "/dem/v", "/dem/omega", "/fluid/populations"});
  fs::remove_all(full);
  fs::remove_all(part);
}

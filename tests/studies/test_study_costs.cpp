// The study tables' cost split (studies/study_case.hpp) on constructed run folders with
// hand-computed answers: the phase table parser (the last table after an offset, names with
// spaces and colons), the per-part wall seconds per simulated second from summed phases and from
// the last invocation's shares, and the coarse-graining speed-up columns against their ideals; and
// the cost sums a checkpoint carries from one invocation to the next (run_cost.hpp).
#include <catch2/catch.hpp>

#include "core/h5.hpp"
#include "core/phase_timer.hpp"
#include "run/run_cost.hpp"
#include "studies/study_case.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace lbdem::run;
using namespace lbdem::studies;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// A log as a run writes it: banner, progress, and a phase table per invocation.
std::string log_text(int particles, double dem_dt, int cells, double gas_dt,
                     const std::string& tables) {
  std::ostringstream s;
  s << "lbdem running fluidized_bed in x with 2 threads\n"
    << "DEM derived numbers:\n"
    << "  particles                                   " << particles << "          \n"
    << "  time step dt                          " << dem_dt << " s        \n"
    << "gas derived numbers:\n"
    << "  cells per axis                                 20          x 20 x 150 = " << cells
    << " cells, 9.12 MB of populations\n"
    << "  gas time step dt                      " << gas_dt << " s        (Dp / (rho c_s^2))\n"
    << tables;
  return s.str();
}

std::string table(double gas, double dem, double coupling, double output) {
  std::ostringstream s;
  const double sum = gas + dem + coupling + output;
  s << "wall time by phase (this invocation; run.phase_timers = false turns the timers off):\n"
    << "  gas: stream-collide                 " << 0.75 * gas << " s   " << 75 * gas / sum << " %\n"
    << "  gas: boundaries                     " << 0.25 * gas << " s   1.0 %\n"
    << "  DEM: particle contacts              " << dem << " s   2.0 %\n"
    << "  coupling: interpolation and drag    " << coupling << " s   3.0 %\n"
    << "  output                              " << output << " s    0.2 %\n"
    << "  rest (set-up, steering, plots)      0 s    0.0 %\n";
  return s.str();
}

// study_phases.txt as a map from phase to seconds.
std::map<std::string, double> phase_sums(const std::string& dir) {
  std::map<std::string, double> out;
  for (const auto& [name, sec] : read_phase_sums(dir)) out[name] = sec;
  return out;
}

}  // namespace

TEST_CASE("Study costs: the last phase table after an offset is read whole", "[studies]") {
  const fs::path dir =
      fs::temp_directory_path() / ("lbdem_test_study_costs_parse_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string first = log_text(100, 1e-6, 1000, 2e-6, table(8, 4, 2, 1));
  write(dir / "log.txt", first + "resumed from checkpoint\n" + table(80, 40, 20, 10) +
                             "t = 0.5 s progress after the table\n");
  const auto all = read_phase_table((dir / "log.txt").string());
  REQUIRE(all.size() == 6);
  CHECK(all[0].first == "gas: stream-collide");
  CHECK(all[0].second == Approx(60));
  CHECK(all[3].first == "coupling: interpolation and drag");
  CHECK(all[3].second == Approx(20));
  CHECK(all[5].first == "rest (set-up, steering, plots)");
  // From an offset inside the first invocation's lines: still the second table. From past the
  // end: none.
  CHECK(read_phase_table((dir / "log.txt").string(), 10)[2].second == Approx(40));
  CHECK(read_phase_table((dir / "log.txt").string(), 1 << 20).empty());
  CHECK(banner_number((dir / "log.txt").string(), "particles") == 100);
  CHECK(banner_number((dir / "log.txt").string(), "gas time step dt") == Approx(2e-6));
  CHECK(banner_number((dir / "log.txt").string(), "cells per axis", true) == 1000);
  CHECK(banner_number((dir / "log.txt").string(), "no such key") == 0);
  fs::remove_all(dir);
}

TEST_CASE("Study costs: parts per simulated second, and speed-ups against their ideals",
          "[studies]") {
  const fs::path root =
      fs::temp_directory_path() / ("lbdem_test_study_costs_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path ref = root / "cg1", cg = root / "cg2";
  fs::create_directories(ref);
  fs::create_directories(cg);
  // Reference: 2,200 s of wall for 0.5 s simulated (4,400 s/s); its phases summed over the
  // invocations in study_phases.txt: gas 1,000 s, DEM 800 s, coupling 150 s, output 50 s; the
  // other 200 s (set-up, plots) lie outside the timed span and go to the rest.
  write(ref / "log.txt", log_text(8000, 1e-6, 60000, 2e-6, table(1, 1, 1, 1)));
  write(ref / "study_timing.txt", "2200 0.5\n");
  write(ref / "study_phases.txt",
        "750\tgas: stream-collide\n250\tgas: boundaries\n800\tDEM: particle contacts\n"
        "150\tcoupling: interpolation and drag\n50\toutput\n");
  // The parcels (l = 2): 1,000 parcels at twice the step, the same gas grid at 1.5 times its
  // step; 300 s for 0.6 s (500 s/s), no sums kept, so the last table's shares: gas 50 %, DEM
  // 20 %, coupling 20 %, rest 10 %.
  write(cg / "log.txt", log_text(1000, 2e-6, 60000, 3e-6,
                                 table(90, 10, 20, 10) + "resumed\n" + table(50, 20, 20, 10)));
  write(cg / "study_timing.txt", "300 0.6\n");

  const PartCosts r = part_costs(ref.string());
  CHECK(r.split);
  CHECK_FALSE(r.from_shares);
  CHECK(r.total == Approx(4400));
  CHECK(r.gas == Approx(2000));
  CHECK(r.dem == Approx(1600));
  CHECK(r.coupling == Approx(300));
  CHECK(r.rest == Approx(500));
  const PartCosts p = part_costs(cg.string());
  CHECK(p.from_shares);
  CHECK(p.total == Approx(500));
  CHECK(p.gas == Approx(250));
  CHECK(p.dem == Approx(100));
  CHECK(p.coupling == Approx(100));

  // gas, DEM, coupling s/s; speed-up 4400 / 500 = 8.8; DEM 1600 / 100 = 16 against the ideal
  // 8000 / 1000 x 2 = 16; gas 2000 / 250 = 8 against 60000 / 60000 x 1.5 = 1.5; gas bounds it.
  // Sums the study kept (two numbers in study_timing.txt) have no timed_from_s.
  CHECK(speedup_columns(cg.string(), ref.string()) == "250,100,100,8.8,16,16,8,1.5,gas,");
  // Without a reference the speed-ups are blank; a case without timing has nothing.
  CHECK(speedup_columns(cg.string(), "") == "250,100,100,,,,,,gas,");
  CHECK(speedup_columns((root / "none").string(), ref.string()) == ",,,,,,,,,");
  // The run's own sums (run_cost.hpp), here from a checkpoint at 0.04 s on.
  write(cg / "study_timing.txt", "300 0.6 0.04\n");
  CHECK(timed_from(cg.string()) == 0.04);
  CHECK(speedup_columns(cg.string(), "") == "250,100,100,,,,,,gas,0.04");
  fs::remove_all(root);
}

TEST_CASE("Study costs: the checkpoint's sums carry over, by phase name, or begin at an old one",
          "[studies]") {
  const fs::path dir =
      fs::temp_directory_path() / ("lbdem_test_run_cost_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string old_ck = (dir / "old.h5").string(), ck = (dir / "ck.h5").string(),
                    next = (dir / "next.h5").string();
  {  // A checkpoint of an lbdem that kept no sums.
    lbdem::H5Out f(old_ck);
    f.attr("format", std::string("lbdem-checkpoint-1"));
    f.commit();
  }
  CHECK_FALSE(read_run_cost(old_ck));
  // Resumed from it at t = 0.04: the sums begin there, with nothing before.
  lbdem::PhaseTimer& timer = lbdem::PhaseTimer::global();
  // One invocation: resumed from `from` at t0, its phases booked, saved into `to` at t1.
  const auto invocation = [&](const std::string& from, double t0, const std::string& to, double t1,
                              const auto& book) {
    timer.reset();  // as run_scenario does
    RunCostMeter m;
    m.resume(lbdem::H5In(from), t0);
    book();
    lbdem::H5Out f(to);
    m.save(f, t1);
    f.commit();
  };
  invocation(old_ck, 0.04, ck, 0.05, [&] { timer.add(lbdem::Phase::dem_pair_contacts, 3.0); });
  const auto c = read_run_cost(ck);
  REQUIRE(c);
  CHECK(c->from_s == 0.04);
  CHECK(c->to_s == 0.05);
  CHECK(c->wall_s >= 0);
  for (const auto& [name, sec] : c->phases)
    CHECK(sec == (name == "DEM: particle contacts" ? 3.0 : 0.0));
  // A checkpoint whose sums a later lbdem wrote, by hand: its phases in another order, one of them
  // unknown here, and a wall time far above anything this test spends (100 s).
  {
    lbdem::H5Out f(ck);
    f.group("/timing");
    f.write("/timing/phase_s", std::vector<double>{2.0, 5.0, 1.0});
    f.attr("phases", std::string("output\na phase of a later lbdem\nDEM: particle contacts\n"),
           "/timing");
    f.attr("from_s", 0.01, "/timing");
    f.attr("to_s", 0.05, "/timing");
    f.attr("wall_s", 100.0, "/timing");
    f.commit();
  }
  // The next invocation adds its own seconds to the stored ones, phase by phase and by name, and
  // keeps where the sums began; the unknown phase is dropped (its seconds stay in the wall time).
  invocation(ck, 0.05, next, 0.06, [&] {
    timer.add(lbdem::Phase::dem_pair_contacts, 2.0);
    timer.add(lbdem::Phase::lbm_collide_stream, 7.0);
  });
  const auto d = read_run_cost(next);
  REQUIRE(d);
  CHECK(d->from_s == 0.01);
  CHECK(d->to_s == 0.06);
  CHECK(d->wall_s >= 100.0);
  CHECK(d->wall_s < 200.0);  // this invocation's own seconds: a few milliseconds
  double contacts = -1, collide = -1, output = -1;
  for (const auto& [name, sec] : d->phases) {
    CHECK(name != "a phase of a later lbdem");
    if (name == "DEM: particle contacts") contacts = sec;
    if (name == "gas: stream-collide") collide = sec;
    if (name == "output") output = sec;
  }
  // Exact: sums of small integers in binary.
  CHECK(contacts == 3.0);  // 1 stored + 2
  CHECK(collide == 7.0);
  CHECK(output == 2.0);
  timer.reset();
  fs::remove_all(dir);
}

TEST_CASE("Study costs: a study case is timed from its run's checkpoint sums across a resume",
          "[studies][checkpoint]") {
  const fs::path root =
      fs::temp_directory_path() / ("lbdem_test_study_case_cost_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const std::string dir = (root / "box150").string();
  // The small box of test_box_cli.cpp (150 particles, about a second per 0.03 s).
  const StudyCase sc{
      "box150",
      "box",
      std::string(LBDEM_SOURCE_DIR) + "/scenarios/box/presets/default.toml",
      {"fill[0].count=150", "fill[0].lo=[0.0,0.0,0.0]", "fill[0].hi=[0.06,0.06,0.03]",
       "output.checkpoint_interval=0.03", "run.end_time=0.03"}};
  StudyOptions opt;
  opt.threads = 1;
  opt.no_plots = true;
  REQUIRE(run_study_case(root.string(), sc, opt, "test") == 0);
  const auto [wall1, sim1] = read_timing(dir);
  CHECK(timed_from(dir) == 0);
  CHECK(sim1 == Approx(0.03).margin(1e-4));  // 0.03 s on a whole step
  CHECK(wall1 > 0);
  const auto phases1 = phase_sums(dir);
  // Extended to 0.06 s: resumed, and timed from the start over both invocations.
  opt.end_time = 0.06;
  REQUIRE(run_study_case(root.string(), sc, opt, "test") == 0);
  const auto [wall2, sim2] = read_timing(dir);
  CHECK(timed_from(dir) == 0);
  CHECK(sim2 == Approx(0.06).margin(1e-4));
  CHECK(wall2 > wall1);
  const auto phases2 = phase_sums(dir);
  REQUIRE(phases1.count("DEM: particle contacts"));
  CHECK(phases2.at("DEM: particle contacts") > phases1.at("DEM: particle contacts"));
  fs::remove_all(root);
}

#include "scenarios/run_command.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>

#include "core/config.hpp"
#include "core/phase_timer.hpp"
#include "core/run_clock.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/log.hpp"
#include "scenarios/box/box.hpp"
#include "run/checkpoint_check.hpp"
#include "scenarios/fluidized_bed/fluidized_bed.hpp"
#include "scenarios/jet_mill/jet_mill.hpp"
#include "scenarios/rheometer/rheometer.hpp"

namespace lbdem::scenarios {

namespace fs = std::filesystem;

namespace {

// The status after a failure, written whatever the failure left: atomically if that works, else
// in place (on a full disk the old status's own block is what there is), else not at all (the
// error on stderr says it).
void write_status(const std::string& dir, const std::string& text) {
  try {
    write_file_atomic(dir + "/status", text);
  } catch (const std::exception&) {
    std::ofstream(dir + "/status", std::ios::trunc) << text;
  }
}

struct ScenarioEntry {
  std::string name, description, preset;
  std::function<std::unique_ptr<Scenario>(const Config&)> make;
};

template <class S>
std::unique_ptr<Scenario> make(const Config& c) {
  return std::make_unique<S>(c);
}

// Checked-in table of scenarios (docs/architecture.md, Adding a scenario).
const std::vector<ScenarioEntry>& scenarios() {
  static const std::vector<ScenarioEntry> table = {
      {"box",
       "particles poured into a box and settling; faces wall/periodic/open, STL walls, inflow",
       "scenarios/box/presets/default.toml", make<BoxScenario>},
      {"fluidized_bed",
       "gas-fluidized bed of fine (cohesive) particles, original or coarse-grained",
       "scenarios/fluidized_bed/presets/default.toml", make<FluidizedBedScenario>},
      {"jet_mill",
       "spiral jet mill: LES gas vortex from grinding jets, coupled coarse-grained feed",
       "scenarios/jet_mill/presets/default.toml", make<JetMillScenario>},
      {"rheometer", "powder rheometer: impeller torque in a cup of powder (Anton Paar powder cell)",
       "scenarios/rheometer/presets/default.toml", make<RheometerScenario>},
  };
  return table;
}

std::string stamp() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&t));
  return buf;
}

void make_plots(const std::string& dir, Log& log) {
  const std::string py = LBDEM_PYTHON;
  if (py.empty()) {
    log.line(
        "plots skipped: no python3 with numpy, h5py and matplotlib was found at configure time");
    return;
  }
  const std::string tools = std::string(LBDEM_SOURCE_DIR) + "/tools/";
  const std::string cmd = "'" + py + "' '" + tools + "plot_run.py' '" + dir + "' > /dev/null && '" +
                          py + "' '" + tools + "collision_summary.py' '" + dir + "' > /dev/null";
  if (std::system(cmd.c_str()) != 0) log.line("warning: the plotting tools failed (" + cmd + ")");
}

// The time this invocation stood suspended (run_clock.hpp), if any.
void log_suspension(Log& log, double suspended_before) {
  if (const double held = suspended_seconds() - suspended_before; held > 0)
    log.line("suspended (SIGTSTP) for " + to_text(held) + " s, left out of the wall times");
}

// The phase table at the end of log.txt, for a finished or a stopped run alike.
void log_phase_times(Log& log, RunClock::duration elapsed) {
  if (!PhaseTimer::global().enabled()) return;
  std::string table = PhaseTimer::global().table(std::chrono::duration<double>(elapsed).count());
  table.pop_back();  // the last line's newline: Log::line adds one
  log.line(
      "wall time by phase (this invocation; run.phase_timers = false turns the timers off):\n" +
      table);
}

// The keys the run command reads itself, beside the scenario's: the file's scenario (a file written
// for another one is refused rather than read with the wrong scenario's defaults) and whether the
// phase timers run.
bool read_command_keys(const Config& cfg, const std::string& name) {
  if (const std::string in_file = cfg.get_string("scenario", name); in_file != name)
    throw InputError("scenario", in_file,
                     "the config file is for this scenario, the command names '" + name + "'",
                     "drop the scenario name from the command, or use that scenario's config");
  return cfg.section("run").get_bool("phase_timers", true);
}

// Whether the run in `dir` got past its start: a checkpoint after t = 0.
bool simulated_any(const std::string& dir) {
  if (fs::exists(dir + "/" + kPreviousCheckpoint)) return true;
  try {
    return checkpoint_time(H5In(dir + "/checkpoint.h5")) > 0;
  } catch (const std::exception&) {
    return false;  // none, or none readable: nothing past the start was kept
  }
}

}  // namespace

std::vector<std::string> scenario_names() {
  std::vector<std::string> names;
  for (const auto& s : scenarios()) names.push_back(s.name);
  return names;
}

std::vector<std::string> read_as_scenario(const std::string& name, const Config& cfg) {
  for (const auto& s : scenarios())
    if (s.name == name) {
      read_command_keys(cfg, name);
      const auto columns = s.make(cfg)->columns();
      cfg.check_unknown_keys();
      return columns;
    }
  throw InputError("scenario", name, "unknown scenario", "see ./lbdem run --list");
}

int run_scenario(const RunOptions& opt) {
  if (opt.list) {
    for (const auto& s : scenarios()) std::cout << s.name << "  " << s.description << "\n";
    return 0;
  }
  // Suspending a run (kill -TSTP) to free the cores stops its clocks too (run_clock.hpp).
  install_suspend_handler();
  const double suspended0 = suspended_seconds();
  const bool resume = !opt.resume.empty();
  std::string name = opt.scenario;
  if (resume && !fs::is_directory(opt.resume))
    throw InputError("--resume", opt.resume,
                     fs::exists(opt.resume) ? "is a file, not a run folder" : "no such folder",
                     "give the run folder of the run to continue (its --out)");
  if (resume && !fs::exists(opt.resume + "/checkpoint.h5") &&
      !fs::exists(opt.resume + "/" + kPreviousCheckpoint))
    throw InputError("--resume", opt.resume, "no checkpoint.h5 in that folder",
                     "give a run folder that has one");
  const ScenarioEntry* entry = nullptr;
  if (resume && name.empty() && fs::exists(opt.resume + "/config.toml"))
    name = Config::from_file(opt.resume + "/config.toml").get_string("scenario", "box");
  // A config file names its scenario: `run --config FILE` needs no name.
  if (!resume && name.empty() && !opt.config.empty() && fs::is_regular_file(opt.config))
    name = Config::from_file(opt.config).get_string("scenario", "");
  for (const auto& s : scenarios())
    if (s.name == name) entry = &s;
  if (!entry) {
    std::vector<std::string> names;
    for (const auto& s : scenarios()) names.push_back(s.name);
    if (name.empty())
      throw InputError("scenario", "(none)", "no scenario named",
                       "name one (./lbdem run SCENARIO, see --list) or write scenario = \"...\" "
                       "at the top of the config file");
    throw InputError(
        "scenario", name, "unknown scenario",
        names.empty() ? "" : "did you mean '" + nearest(name, names) + "'? (./lbdem run --list)");
  }
  const std::string file =
      resume
          ? opt.resume + "/config.toml"
          : (opt.config.empty() ? std::string(LBDEM_SOURCE_DIR) + "/" + entry->preset : opt.config);
  if (!fs::exists(file))
    throw InputError("--config", file, "file not found", "give the path of a TOML file");
  Config cfg = Config::from_file(file);
  for (const auto& s : opt.sets) {
    // A resumed run continues the same physics: only its end and its output may change.
    const std::string key = s.substr(0, s.find('='));
    if (resume && key != "run.end_time" && key.rfind("output.", 0) != 0)
      throw InputError("--set", s, "only run.end_time and output.* can change when resuming",
                       "start a new run (--config " + file + ") to change anything else");
    cfg.set_override(s);
  }
  // Recorded, so the resolved config names its scenario. Wall time per phase, printed at the end
  // of log.txt (core/phase_timer.hpp).
  PhaseTimer::global().enable(read_command_keys(cfg, name));
  if (opt.threads > 0) omp_set_num_threads(opt.threads);

  // Validates everything; throws InputError before any output.
  const std::unique_ptr<Scenario> scenario = entry->make(cfg);
  cfg.check_unknown_keys();

  const std::string dir =
      resume ? opt.resume : (opt.out.empty() ? "runs/" + name + "-" + stamp() : opt.out);
  // What every checkpoint records; a resume is checked against it before anything is written
  // (checkpoint_check.hpp), so a refused one leaves the folder, status included, as it was.
  const RunIdentity identity = run_identity(name, cfg, scenario->lattice());
  ResumePoint point;
  if (resume) {
    point = check_resume(dir, identity, scenario->output().end_time);
    if (point.finished) {
      std::cout << "the run in " << dir << " finished at t = " << to_text(point.time_s)
                << " s (run.end_time = " << to_text(point.finished_end_time)
                << " s); nothing to do, nothing changed: raise run.end_time (--set "
                   "run.end_time=...) to extend it\n";
      return 0;
    }
  }
  const bool made_dir = !resume && !fs::exists(dir);
  if (!resume) {
    if (fs::exists(dir) && !fs::is_empty(dir))
      throw InputError("--out", dir, "folder exists and is not empty",
                       "choose another --out, or continue it with --resume " + dir);
    fs::create_directories(dir);
  }
  Log log;
  log.open(dir + "/log.txt", resume);
  write_file_atomic(dir + "/config.toml", cfg.resolved_toml());
  write_file_atomic(dir + "/status", "running\n");
  log.line("lbdem " + std::string(resume ? "resuming " : "running ") + name + " in " + dir +
           " with " + std::to_string(omp_get_max_threads()) + " threads");
  for (const auto& w : point.warnings) log.line(w);
  if (std::isinf(scenario->output().checkpoint_interval))
    log.line(
        "warning: output.checkpoint_interval = \"never\": checkpoints are written only at the "
        "start, at the end and when Ctrl-C or SIGTERM stops the run; a run killed outright "
        "(SIGKILL, a lost machine) cannot be resumed");
  scenario->banner(log);
  const RunContext ctx{
      dir, resume, omp_get_max_threads(), &log, !opt.no_plots, point.checkpoint, &identity};
  // A resumed run's wall time covers what this invocation simulated, from its checkpoint on.
  const double t_start = resume ? point.time_s : 0.0;
  PhaseTimer::global().reset();
  const auto t0 = RunClock::now();
  int rc = 0;
  try {
    rc = scenario->run(ctx);
  } catch (const Interrupted& e) {
    write_status(dir, "stopped (resume with ./lbdem run --resume " + dir + ")\n");
    log.line(std::string(e.what()) + "; resume with ./lbdem run --resume " + dir);
    log_phase_times(log, RunClock::now() - t0);
    log_suspension(log, suspended0);
    return 130;
  } catch (const InputError&) {
    // An input error that shows only once the run goes (the first neighbour search finds a
    // periodic box too short) before any time was simulated: the folder holds no result and is
    // removed, as no folder is made for any other input error. Later, the output stays.
    if (!resume && !simulated_any(dir)) {
      std::error_code ec;
      if (made_dir)
        fs::remove_all(dir, ec);
      else {  // an empty folder given by --out stays, empty
        std::vector<fs::path> made;
        for (const auto& e : fs::directory_iterator(dir, ec)) made.push_back(e.path());
        for (const auto& p : made) fs::remove_all(p, ec);
      }
      throw;
    }
    write_status(dir, "failed (resume with ./lbdem run --resume " + dir + ")\n");
    throw;
  } catch (const WriteError& e) {
    const bool resumable = fs::exists(dir + "/checkpoint.h5");
    write_status(dir, std::string("failed (") + (e.disk_full() ? "disk full: " : "") + e.what() +
                          (resumable ? "; free space and resume with ./lbdem run --resume " + dir
                                     : std::string("; no checkpoint was written: free space and "
                                                   "start the run again")) +
                          ")\n");
    throw;
  } catch (const Diverged&) {
    // The same input diverges again from the kept checkpoint (a resume keeps the physics).
    write_status(dir,
                 "failed (diverged; the last checkpoint is from before; log.txt names the fix, "
                 "for a new run)\n");
    throw;
  } catch (...) {
    write_status(dir, "failed (resume with ./lbdem run --resume " + dir + ")\n");
    throw;
  }
  const double wall = std::chrono::duration<double>(RunClock::now() - t0).count();
  log.line("wall time " + to_text(wall) + " s; wall time per simulated second " +
           to_text(wall / std::max(1e-300, scenario->output().end_time - t_start)) + " s/s");
  log_suspension(log, suspended0);
  log_phase_times(log, RunClock::now() - t0);
  if (ctx.plots) make_plots(dir, log);
  write_file_atomic(dir + "/status", "finished\n");
  std::cout << "run folder: " << fs::absolute(dir).string() << "\n ";
  for (const char* file : {"config.toml", "log.txt", "timeseries.csv", "particles.h5",
                           "particles.xdmf", "collisions.h5", "checkpoint.h5", "fluid.h5",
                           "fluid.xdmf", "energy_budget.png", "kinetic_energy.png", "gas.png"})
    if (fs::exists(dir + "/" + file)) std::cout << " " << file;
  std::cout << "\n";
  return rc;
}

}  // namespace lbdem::scenarios

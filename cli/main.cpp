// lbdem-cli: parse the command line (CLI11), read the TOML, build the scenario, run it.
#include <CLI/CLI.hpp>
#include <hdf5.h>

#include <iostream>

#include "core/error.hpp"
#include "run/run_loop.hpp"
#include "scenarios/run_command.hpp"
#include "studies/study_command.hpp"

int main(int argc, char** argv) {
  using namespace lbdem::scenarios;
  using lbdem::studies::StudyOptions;
  // Every file is closed by its owner before exit. HDF5's own clean-up at exit would close again a
  // file whose close failed (a full disk) and crash after the error was reported.
  H5dont_atexit();
  CLI::App app{"lbdem: coarse-grained CFD-DEM (lattice Boltzmann gas + OpenMP DEM)"};
  app.require_subcommand(1);
  RunOptions opt;
  auto* run = app.add_subcommand("run", "run a scenario's default preset or a config file");
  run->add_option("scenario", opt.scenario, "scenario name (see --list)");
  run->add_option("--config", opt.config,
                  "TOML config file (default: the scenario's default preset)");
  run->add_option("--set", opt.sets, "override a key: --set key.path=value (repeatable)");
  run->add_option("--out", opt.out, "run folder (default: runs/<scenario>-<date>-<time>)");
  run->add_option("--threads", opt.threads, "OpenMP threads (default: all cores)");
  run->add_option("--resume", opt.resume, "continue the run in RUN_DIR from its checkpoint.h5");
  run->add_flag("--list", opt.list, "list the scenarios");
  run->add_flag("--no-plots", opt.no_plots, "skip the PNG plots");
  auto* config = app.add_subcommand(
      "config", "print the reference of every config key (markdown; docs/config.md is its output)");
  auto* study = app.add_subcommand("study", "run a multi-run study");
  StudyOptions so;
  study->add_option("name", so.name, "study name (see --list)");
  study->add_option("--cases", so.cases, "run only these cases (comma separated)")->delimiter(',');
  study
      ->add_option("--end-time", so.end_time,
                   "simulated end time of every case [s] (a measured window; default: presets)")
      ->check(CLI::PositiveNumber);
  study->add_option("--set", so.sets, "override a key in every new case (repeatable)");
  study->add_option("--out", so.out, "study folder (default: runs/studies/<name>)");
  study->add_option("--threads", so.threads, "OpenMP threads (default: all cores)");
  study->add_flag("--no-plots", so.no_plots, "skip the PNG plots");
  study->add_flag("--list", so.list, "list the studies");
  study->add_flag("--no-run", so.no_run,
                  "compare the cases already in the study folder; run and resume none");
  study
      ->add_option("--from", so.window_from,
                   "start of the statistics window [s] (fluidized_bed: default 0.05 s after the "
                   "gas ramp; cg: default half the end time)")
      ->check(CLI::PositiveNumber);
  study
      ->add_option("--to", so.window_to,
                   "end of the statistics window [s] (fluidized_bed, cg; default: each case's "
                   "end)")
      ->check(CLI::PositiveNumber);
  study->add_option("--config", so.config, "cg: the config to coarse-grain (TOML file)");
  study
      ->add_option("--levels", so.levels,
                   "cg: size factors to run and compare, comma separated (the smallest is the "
                   "reference)")
      ->delimiter(',');
  study->add_option("--level-set", so.level_sets,
                    "cg: an override for one level only, L:key=value (repeatable), e.g. "
                    "4:fluid.dx=0.0004 for a gas grid that coarsens with the parcels");
  study
      ->add_option("--observables", so.observables,
                   "cg: timeseries.csv columns to compare (default: the scenario's: bed height "
                   "and pressure drop, torque, or kinetic energy)")
      ->delimiter(',');
  study->add_option("--rule", so.rule,
                    "cg: coarse_grain.rule of every level (default: the config's)");
  study
      ->add_option("--tolerance", so.tolerance,
                   "cg: a resolved relative difference up to this is called close (default "
                   "0.05)")
      ->check(CLI::NonNegativeNumber);
  study->add_flag("--quick", so.quick,
                  "a short check of the whole chain at reduced size and end time (jet_mill)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints help or the error
    return rc == 0 ? 0 : lbdem::kInputErrorExit;
  }
  try {
    // Checked here rather than by CLI11, whose range message is two lines without a fix.
    const int threads = *study ? so.threads : opt.threads;
    if ((*study ? study : run)->count("--threads") && threads < 1)
      throw lbdem::InputError("--threads", std::to_string(threads), "must be at least 1",
                              "give a thread count >= 1, or leave --threads out to use all cores");
    if (*config) return print_config_reference();
    if (*study) return lbdem::studies::run_study(so);
    return run_scenario(opt);
  } catch (const lbdem::InputError& e) {
    std::cerr << "lbdem: error: " << e.what() << "\n";
    return lbdem::kInputErrorExit;
  } catch (const lbdem::run::Diverged& e) {
    std::cerr << "lbdem: error: " << e.what() << "\n";
    return lbdem::run::kDivergedExit;
  } catch (const std::exception& e) {
    std::cerr << "lbdem: failed: " << e.what() << "\n";
    return 1;
  }
}

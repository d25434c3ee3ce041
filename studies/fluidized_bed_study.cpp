#include "studies/fluidized_bed_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "core/config.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/types.hpp"
#include "studies/study_case.hpp"
#include "tools/src/run_comparison.hpp"

namespace lbdem::studies {

namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name, cohesion;  // cohesion: "none", or the rule of a cohesive case
  double l, bond;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> c = {
      {"cg1", "none", 1, 0},
      {"cg2", "none", 2, 0},
      {"cg3", "none", 3, 0},
      {"cg4", "none", 4, 0},
      {"cg3_wide", "none", 3, 0},
      {"cg4_wide", "none", 4, 0},
      {"cg1_bo10", "(l = 1)", 1, 10},
      {"cg2_bo10_l2", "tensile_strength (l^2)", 2, 10},
      {"cg2_bo10_l3", "bond_number (l^3)", 2, 10},
      {"cg4_bo10_l2", "tensile_strength (l^2)", 4, 10},
      {"cg4_bo10_l3", "bond_number (l^3)", 4, 10},
      {"cg1_bo1", "(l = 1)", 1, 1},
      {"cg1_bo30", "(l = 1)", 1, 30},
  };
  return c;
}

}  // namespace

int run_fluidized_bed_study(const StudyOptions& opt) {
  std::vector<const Case*> todo;
  std::vector<std::string> names;
  for (const auto& c : cases()) names.push_back(c.name);
  check_case_names(opt.cases, names, "fluidized_bed");
  for (const std::size_t k : cases_to_run(opt.cases, names, std::vector<bool>(names.size(), true)))
    todo.push_back(&cases()[k]);
  const std::string root = opt.out.empty() ? "runs/studies/fluidized_bed" : opt.out;
  fs::create_directories(root);
  const std::string src = LBDEM_SOURCE_DIR;
  for (const Case* c : todo) {
    const StudyCase sc{c->name,
                       "fluidized_bed",
                       src + "/scenarios/fluidized_bed/presets/" + c->name + ".toml",
                       {}};
    if (const int rc = run_study_case(root, sc, opt, "fluidized_bed study"); rc != 0) return rc;
  }

  // Every case of the folder that has output, compared over the fluidized window.
  std::vector<const Case*> present;
  double from = 0;
  for (const auto& c : cases()) {
    const std::string dir = root + "/" + c.name;
    if (!fs::exists(dir + "/config.toml") || last_time(dir + "/timeseries.csv") <= 0) continue;
    const Config cfg = Config::from_file(dir + "/config.toml");
    const Config inlet = cfg.section("fluid").section("faces").section("z_lo");
    from = opt.window_from > 0
               ? opt.window_from
               : std::max(from, inlet.get("ramp_start", 0.0) + inlet.get("ramp_time", 0.0) + 0.05);
    present.push_back(&c);
  }
  // A case with fewer rows in the window than the comparison needs (a CG 1 run that has not got
  // far enough yet) has nothing to compare: it stays in the table without statistics.
  const std::string python = LBDEM_PYTHON;
  const std::array<std::string, 2> columns = {"bed_height_m", "pressure_drop_Pa"};
  std::array<std::map<std::string, tools::RunStats>, 2> stats;
  std::array<std::vector<tools::RunStats>, 2> compared;
  for (const Case* c : present) {
    const tools::RunFolder run = tools::RunFolder::open(root + "/" + c->name);
    const double to = opt.window_to > 0 ? opt.window_to : 1e300;
    const std::size_t rows = tools::select_window(run.time(), from, to).size();
    if (rows < tools::kMinWindowSamples) {
      std::cerr << "fluidized_bed study: " << c->name << " has " << rows << " rows from " << from
                << " s (" << tools::kMinWindowSamples
                << " needed): in the table without statistics\n";
      continue;
    }
    for (std::size_t k = 0; k < columns.size(); ++k) {
      try {
        const tools::RunStats r = tools::analyse_run(run, c->name, {columns[k], from, to});
        stats[k][c->name] = r;
        compared[k].push_back(r);
      } catch (const tools::ToolError& e) {
        std::cerr << "warning: " << c->name << ": " << e.what() << "\n";
      }
    }
  }
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (compared[k].empty()) continue;
    const std::string prefix = root + "/" + columns[k];
    tools::write_comparison(prefix, columns[k], compared[k]);
    write_file_atomic(prefix + "_table.txt", tools::comparison_table(columns[k], compared[k]));
    if (!opt.no_plots && !python.empty()) {
      const std::string plot = shell_quoted(python) + " " +
                               shell_quoted(src + "/tools/compare_runs.py") + " " +
                               shell_quoted(prefix) + " > /dev/null";
      if (std::system(plot.c_str()) != 0)
        std::cerr << "warning: the plot failed (" << plot << ")\n";
      else
        std::cout << "plot: " << fs::absolute(prefix + ".png").string() << "\n";
    }
  }

  std::ostringstream table;
  table << "case,size_factor,cohesion_rule,bond_number,parcels,parcels_across,parcels_high,"
           "window_from_s,simulated_s,bed_height_m,bed_height_err_m,bed_height_std_m,"
           "bed_height_std_err_m,pressure_drop_Pa,pressure_drop_err_Pa,pressure_drop_std_Pa,"
           "pressure_drop_std_err_Pa,weight_per_area_Pa,"
           "wall_s_per_simulated_s,"
        << kSpeedupColumns << "\n";
  for (const Case* c : present) {
    const std::string dir = root + "/" + c->name;
    const Config cfg = Config::from_file(dir + "/config.toml");
    const auto hi = cfg.section("box").get_list("hi", {0, 0, 0});
    const double d = 100e-6 * c->l, rho = 1500;
    const double mass = cfg.table_array("fill").front().get("mass", 0.0);
    const double parcels = mass / (rho * kPi * d * d * d / 6);
    const double area = hi[0] * hi[1];
    const auto [wall, timed] = read_timing(dir);
    table << c->name << "," << c->l << "," << c->cohesion << "," << c->bond << ","
          << fmt(std::ceil(parcels - 1e-9), "%.0f") << "," << fmt(hi[0] / d) << ","
          << fmt(mass / (rho * 0.6 * area) / d) << "," << fmt(from) << ","
          << fmt(last_time(dir + "/timeseries.csv"));
    for (std::size_t k = 0; k < 2; ++k) {
      const auto it = stats[k].find(c->name);
      if (it == stats[k].end())
        table << ",,,,";
      else
        table << "," << fmt(it->second.m.mean) << "," << fmt(it->second.err.stderr_mean) << ","
              << fmt(it->second.m.std) << "," << fmt(it->second.std_err.stderr_mean);
    }
    table << "," << fmt(mass * 9.81 * (1 - 1.2 / rho) / area) << ","
          << (wall > 0 && timed > 0 ? fmt(wall / timed) : std::string(""));
    // Against the original (CG 1) at the same Bond number, when it has run.
    const auto ref = std::find_if(present.begin(), present.end(),
                                  [&](const Case* r) { return r->l == 1 && r->bond == c->bond; });
    table << "," << speedup_columns(dir, ref == present.end() ? "" : root + "/" + (*ref)->name)
          << "\n";
  }
  write_file_atomic(root + "/study.csv", table.str());
  std::cout << "fluidized_bed study table: " << fs::absolute(root + "/study.csv").string() << "\n"
            << table.str();
  return 0;
}

}  // namespace lbdem::studies

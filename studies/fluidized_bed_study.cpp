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

std::string fmt(double v, const char* f = "%.4g") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// lbdem-compare-runs' least number of samples in a window (tools/src/compare_runs.cpp).
constexpr std::size_t kMinWindowRows = 16;

// Rows of a timeseries.csv whose time lies in [from, to].
std::size_t rows_in_window(const std::string& csv, double from, double to) {
  std::ifstream f(csv);
  std::string line;
  std::getline(f, line);  // header
  std::size_t n = 0;
  while (std::getline(f, line)) {
    try {
      const double t = std::stod(line.substr(0, line.find(',')));
      if (t >= from && t <= to) ++n;
    } catch (const std::exception&) {
      // a partly written last row of a running case
    }
  }
  return n;
}

// mean, stderr_mean, std and stderr_std of each run folder in a compare-runs stats file.
std::map<std::string, std::array<double, 4>> read_stats(const std::string& path) {
  std::map<std::string, std::array<double, 4>> out;
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  while (std::getline(f, line)) {
    std::vector<std::string> v;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) v.push_back(c);
    if (v.size() < 18) continue;
    out[fs::path(v[0]).filename().string()] = {std::stod(v[8]), std::stod(v[9]), std::stod(v[10]),
                                               std::stod(v[17])};
  }
  return out;
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
  // A case with fewer rows in the window than lbdem-compare-runs needs (a CG 1 run that has not
  // got far enough yet) has nothing to compare: it stays in the table without statistics.
  std::vector<const Case*> compared;
  for (const Case* c : present) {
    const std::size_t rows = rows_in_window(root + "/" + c->name + "/timeseries.csv", from,
                                            opt.window_to > 0 ? opt.window_to : 1e300);
    if (rows >= kMinWindowRows)
      compared.push_back(c);
    else
      std::cerr << "fluidized_bed study: " << c->name << " has " << rows << " rows from " << from
                << " s (" << kMinWindowRows << " needed): in the table without statistics\n";
  }
  const fs::path bin = fs::read_symlink("/proc/self/exe").parent_path();
  const std::string python = LBDEM_PYTHON;
  const std::array<std::string, 2> columns = {"bed_height_m", "pressure_drop_Pa"};
  std::array<std::map<std::string, std::array<double, 4>>, 2> stats;
  for (std::size_t k = 0; k < columns.size() && !compared.empty(); ++k) {
    std::string cmd = "'" + (bin / "lbdem-compare-runs").string() + "' --column " + columns[k] +
                      " --from " + fmt(from, "%.17g") +
                      (opt.window_to > 0 ? " --to " + fmt(opt.window_to, "%.17g") : std::string());
    for (const Case* c : compared) cmd += " '" + root + "/" + c->name + "' --label " + c->name;
    const std::string prefix = root + "/" + columns[k];
    cmd += " --out '" + prefix + "' > '" + prefix + "_table.txt'";
    if (std::system(cmd.c_str()) != 0) {
      std::cerr << "warning: lbdem-compare-runs failed (" << cmd
                << "); a case may not have reached the fluidized window (t > " << from << " s)\n";
      continue;
    }
    stats[k] = read_stats(prefix + "_stats.csv");
    if (!opt.no_plots && !python.empty()) {
      const std::string plot =
          "'" + python + "' '" + src + "/tools/compare_runs.py' '" + prefix + "' > /dev/null";
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
        table << "," << fmt(it->second[0]) << "," << fmt(it->second[1]) << "," << fmt(it->second[2])
              << "," << fmt(it->second[3]);
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

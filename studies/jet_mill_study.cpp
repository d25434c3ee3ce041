#include "studies/jet_mill_study.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "core/config.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "run/run_loop.hpp"
#include "scenarios/common/fluid_config.hpp"
#include "studies/study_case.hpp"
#include "tools/src/collision_summary.hpp"
#include "tools/src/mill_map_files.hpp"
#include "tools/src/run_comparison.hpp"
#include "scenarios/jet_mill/jet_mill_geometry.hpp"

namespace lbdem::studies {

// A study builds on the scenarios' configs, geometry and run command.
using namespace lbdem::scenarios;
using namespace lbdem::run;

namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name;
  int n;  // originals per parcel
  bool in_default;
  // A case whose preset is another's in all but its comments: the study runs that one and links
  // this name to its folder (cg4_fixed: the fixed grid's 0.3125 mm cells are CG-4's scaled ones).
  const char* same_as = nullptr;
};

const std::vector<Case>& cases() {
  // clang-format off
  static const std::vector<Case> c = {
      // The default series: the seed's nozzles at a grinding pressure of 5 bar (results/jet_mill/
      // README.md: an incompressible 120 m/s jet cannot drive the seed's powder speeds).
      {"cg1_p5bar", 1, true}, {"cg2_p5bar", 2, true}, {"cg4_p5bar", 4, true},
      {"cg8_p5bar", 8, true}, {"cg10_p5bar", 10, true},
      // CG-10 of that series with a DEM step of t_c/34 instead of the seed's t_c/8.5.
      {"cg10_p5bar_tc30", 10, false},
      // Incompressible 120 m/s jets, on the scaled cells and on one fixed grid.
      {"cg1", 1, false}, {"cg2", 2, false}, {"cg4", 4, false}, {"cg8", 8, false},
      {"cg10", 10, false}, {"cg10_tc30", 10, false},
      {"cg1_fixed", 1, false}, {"cg2_fixed", 2, false}, {"cg4_fixed", 4, false, "cg4"},
      {"cg8_fixed", 8, false}, {"cg10_fixed", 10, false},
      // The 5 bar nozzles on that fixed grid.
      {"cg1_fixed_p5bar", 1, false}, {"cg2_fixed_p5bar", 2, false},
      {"cg4_fixed_p5bar", 4, false, "cg4_p5bar"}, {"cg8_fixed_p5bar", 8, false},
      {"cg10_fixed_p5bar", 10, false}};
  // clang-format on
  return c;
}

// The study's figures average over its 0.07-0.1 s; --quick over the last 2 ms of its 4 ms.
constexpr double kFrom = 0.07, kTo = 0.1, kQuickEnd = 0.004, kQuickFrom = 0.002;

}  // namespace

FigureWindow figure_window(double spin_up, bool quick, double row_interval) {
  return {spin_up + (quick ? kQuickFrom : kFrom),
          spin_up + (quick ? kQuickEnd : kTo) + 0.5 * row_interval};
}

namespace {

// A table the tools wrote (with its text cells), or an empty one where there is no such file.
tools::Table table_or_empty(const std::string& path) {
  if (!fs::exists(path)) return {};
  try {
    return tools::read_csv(path, true);
  } catch (const tools::ToolError&) {
    return {};
  }
}

// One row of such a table, or none: its numbers by column name, NaN where absent.
struct Row {
  const tools::Table* table = nullptr;
  std::size_t row = 0;
  double operator()(const char* key) const {
    return table ? table->number(key, row) : std::nan("");
  }
};

// The first row of `t`, if it has one.
Row first_row(const tools::Table& t) {
  return t.rows() > 0 ? Row{&t, 0} : Row{};
}

// The row of `t` whose run_dir ends in /name.
Row row_of(const tools::Table& t, const std::string& name) {
  if (!t.has("run_dir") || t.text.empty()) return {};
  for (std::size_t r = 0; r < t.rows(); ++r)
    if (fs::path(t.cell("run_dir", r)).filename() == name) return {&t, r};
  return {};
}

// The last value of a timeseries column and the largest value of another.
std::pair<double, double> last_and_max(const std::string& csv, const std::string& last_col,
                                       const std::string& max_col) {
  const tools::Table t = table_or_empty(csv);
  double last = std::nan(""), mx = std::nan("");
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double a = t.number(last_col, r), b = t.number(max_col, r);
    if (std::isfinite(a)) last = a;
    if (std::isfinite(b)) mx = std::isfinite(mx) ? std::max(mx, b) : b;
  }
  return {last, mx};
}

int system_ok(const std::string& cmd, const char* what) {
  const int rc = std::system(cmd.c_str());
  if (rc != 0) std::cerr << "warning: " << what << " failed (" << cmd << ")\n";
  return rc;
}

}  // namespace

int run_jet_mill_study(const StudyOptions& opt) {
  std::vector<std::string> names;
  for (const auto& c : cases()) names.push_back(c.name);
  check_case_names(opt.cases, names, "jet_mill");
  if (opt.quick && opt.end_time > 0)
    throw InputError("--end-time", fmt(opt.end_time), "--quick sets its own end time",
                     "give --quick or --end-time, not both");
  const std::string root =
      opt.out.empty() ? (opt.quick ? "runs/studies/jet_mill_quick" : "runs/studies/jet_mill")
                      : opt.out;
  fs::create_directories(root);
  const std::string src = LBDEM_SOURCE_DIR;
  // The feed starts after the gas spin-up: study time 0 is inflow.start of the presets.
  const double spin_up = Config::from_file(src + "/scenarios/jet_mill/presets/cg1.toml")
                             .section("inflow")
                             .get("start", 0.0);
  StudyOptions run_opt = opt;
  if (opt.quick) {
    run_opt.end_time = spin_up + kQuickEnd;
    run_opt.sets.insert(run_opt.sets.begin(),
                        {"fluid.dx=1e-3", "output.interval=1e-4", "output.snapshot_interval=5e-4",
                         "output.checkpoint_interval=0.01"});
  }
  std::vector<bool> by_default;
  for (const auto& c : cases()) by_default.push_back(c.in_default);
  for (const std::size_t k : cases_to_run(opt.cases, names, by_default)) {
    const Case& c = cases()[k];
    const std::string run = c.same_as ? c.same_as : c.name;
    const StudyCase sc{run, "jet_mill", src + "/scenarios/jet_mill/presets/" + run + ".toml", {}};
    if (const int rc = run_study_case(root, sc, run_opt, "jet_mill study"); rc != 0) return rc;
    if (!c.same_as) continue;
    const fs::path link = fs::path(root) / c.name;
    if (!fs::exists(fs::symlink_status(link)))
      fs::create_directory_symlink(run, link);
    else if (!fs::is_symlink(link))
      std::cerr << "jet_mill study: " << link.string() << " is a run of its own; " << c.name
                << " is the same case as " << run << " (kept as it is)\n";
  }

  // Every case of the folder that has reached the window's end (with the feed at the presets'
  // time, which sets the window): its last row at most half a row interval short of it (the run
  // rounds its last step to the nearest whole step, then up to a whole exchange cycle).
  const double end = spin_up + (opt.quick ? kQuickEnd : kTo);
  std::vector<const Case*> present;
  double row_interval = std::numeric_limits<double>::infinity();
  for (const auto& c : cases()) {
    const std::string dir = root + "/" + c.name;
    if (!fs::exists(dir + "/config.toml")) continue;
    const double reached = last_time(dir + "/timeseries.csv");
    const Config cfg = Config::from_file(dir + "/config.toml");
    const double start = cfg.section("inflow").get("start", spin_up);
    const double interval =
        OutputSettings::from(cfg.section("run"), cfg.section("output")).interval;
    if (start != spin_up)
      std::cerr << "jet_mill study: " << c.name << " feeds from " << start << " s, not " << spin_up
                << " s: left out (the window is the same for all cases)\n";
    else if (reached < end - 0.5 * interval)
      std::cerr << "jet_mill study: " << c.name << " has reached " << reached
                << " s, not yet the window's end (" << end << " s): left out of the figures\n";
    else {
      present.push_back(&c);
      row_interval = std::min(row_interval, interval);
    }
  }
  if (present.empty()) {
    std::cerr << "jet_mill study: no case has reached the window's end (" << end
              << " s of run time)\n";
    return 0;
  }
  // The window the tools select rows and snapshots in, its end padded to take each run's last
  // row (the figure script only labels its plots with the window, so it gets the unpadded end).
  const auto [from, to] = figure_window(spin_up, opt.quick, row_interval);
  // Outputs of an earlier invocation must not stand in for a tool that fails now.
  for (const char* f : {"collisions.csv", "collisions_impact_speed.csv", "collisions_table.txt",
                        "kinetic_energy_stats.csv", "kinetic_energy_spectra.csv",
                        "kinetic_energy_table.txt", "study.csv"})
    fs::remove(root + "/" + f);
  std::map<std::string, double> dem_dt;
  std::set<std::string> no_maps;  // cases whose mill_summary.csv is not of this window
  double chamber_radius = 0;
  for (const Case* c : present) {
    const std::string dir = root + "/" + c->name;
    const Config cfg = Config::from_file(dir + "/config.toml");
    const Config box = cfg.section("box");
    const FluidConfig f = read_fluid(cfg.section("fluid"), box.require_vec3("lo"),
                                     box.require_vec3("hi"), {false, false, false}, Vec3::Zero());
    const JetMillGeometry g = read_jet_mill(cfg.section("jet_mill"), f);
    chamber_radius = g.radius;
    // The step the run took: the preset's, shortened to a whole fraction or multiple of the gas
    // step (box.cpp), 8-35 % below dem.dt for these presets.
    dem_dt[c->name] = conform_dem_step(cfg.section("dem").get("dt", 0.0), f.dt).dem_dt;
    // A folder of a run's kept small outputs (results/jet_mill/) has no snapshots, and its maps,
    // made by the run's own study from them, are the only copy: they are never removed. They stand
    // for this window if their first snapshot lies within one snapshot interval after its start
    // and their last within 1.5 intervals and a row interval before its (padded) end (the run may
    // stop just before the next snapshot, and snapshots fall on whole steps, a little late).
    if (!fs::exists(dir + "/particles.h5")) {
      const tools::Table kept_table = table_or_empty(dir + "/mill_summary.csv");
      const Row kept = first_row(kept_table);
      const OutputSettings out = OutputSettings::from(cfg.section("run"), cfg.section("output"));
      const double tol = 1e-8 * std::max(std::abs(from), std::abs(to));
      const double a = kept("from_s"), b = kept("to_s");
      const bool covers = a >= from - tol && a <= from + out.snapshot_interval + tol &&
                          b <= to + tol &&
                          b >= to - 1.5 * out.snapshot_interval - out.interval - tol;
      if (covers)
        std::cerr << "jet_mill study: " << c->name
                  << " has no particles.h5; its mill_*.csv maps of the same window are kept\n";
      else {
        std::cerr << "jet_mill study: " << c->name
                  << " has no particles.h5 and no mill_*.csv maps of this window (they are left "
                     "as they are): its speed columns stay empty and the map figures leave it "
                     "out\n";
        no_maps.insert(c->name);
      }
      continue;
    }
    for (const char* m :
         {"speed_map", "wall_profile", "positions", "gas_profile", "gas_midplane", "summary"})
      fs::remove(dir + "/mill_" + m + ".csv");
    tools::MillMapOptions maps;
    maps.dir = dir, maps.prefix = dir + "/mill", maps.from = from, maps.to = to;
    for (const Nozzle& q : g.nozzles)
      if (!q.feed) {
        const double n = std::hypot(q.dir.x(), q.dir.y());
        maps.jets.push_back({Vec3(q.exit.x(), q.exit.y(), 0), Vec3(q.dir.x() / n, q.dir.y() / n, 0),
                             tools::kJetHalfWidth, tools::kJetLength});
      }
    try {
      std::cout << tools::write_mill_maps(maps);
    } catch (const tools::ToolError& e) {
      std::cerr << "warning: no maps of " << c->name << ": " << e.what() << "\n";
    }
  }
  try {
    std::vector<tools::CollisionSummary> coll;
    for (const Case* c : present)
      coll.push_back(tools::analyse_collisions(tools::RunFolder::open(root + "/" + c->name),
                                               c->name, from, to));
    tools::write_collision_csvs(root + "/collisions.csv", coll);
    write_file_atomic(root + "/collisions_table.txt", tools::collision_table(coll));
  } catch (const tools::ToolError& e) {
    std::cerr << "warning: no collision statistics: " << e.what() << "\n";
  }
  try {
    std::vector<tools::RunStats> ke;
    for (const Case* c : present)
      ke.push_back(tools::analyse_run(tools::RunFolder::open(root + "/" + c->name), c->name,
                                      {"kinetic_energy_J", from, to}));
    tools::write_comparison(root + "/kinetic_energy", "kinetic_energy_J", ke);
    write_file_atomic(root + "/kinetic_energy_table.txt",
                      tools::comparison_table("kinetic_energy_J", ke));
  } catch (const tools::ToolError& e) {
    std::cerr << "warning: no kinetic-energy comparison: " << e.what() << "\n";
  }
  const std::string python = LBDEM_PYTHON;
  if (!opt.no_plots && !python.empty()) {
    std::string plot =
        shell_quoted(python) + " " + shell_quoted(src + "/tools/jet_mill_figures.py") + " " +
        shell_quoted(root) + " --from " + fmt(from, "%.17g") + " --to " + fmt(end, "%.17g") +
        " --offset " + fmt(spin_up, "%.17g") + " --radius " + fmt(chamber_radius, "%.17g");
    for (const std::string& name : no_maps) plot += " --no-maps " + name;
    for (const Case* c : present) plot += " " + c->name;
    if (system_ok(plot + " > /dev/null", "tools/jet_mill_figures.py") == 0)
      std::cout << "figures: " << fs::absolute(root).string() << "/*.png\n";
    if (system_ok(shell_quoted(python) + " " + shell_quoted(src + "/tools/collision_stats.py") +
                      " " + shell_quoted(root + "/collisions.csv") + " > /dev/null",
                  "tools/collision_stats.py") == 0)
      std::cout << "plot: " << fs::absolute(root + "/collisions.png").string() << "\n";
  }

  // The table: one row per case.
  const tools::Table coll = table_or_empty(root + "/collisions.csv");
  const tools::Table ke = table_or_empty(root + "/kinetic_energy_stats.csv");
  // Each case is compared with CG 1 of its own series, named after "cgN": the scaled cells ("",
  // and cg10_tc30, cg10 with a shorter DEM step), "_fixed", "_p5bar" (and cg10_p5bar_tc30),
  // "_fixed_p5bar".
  const auto series_ref = [](const std::string& name) {
    const std::size_t us = name.find('_');
    std::string series = us == std::string::npos ? "" : name.substr(us);
    // A shorter DEM step (_tc30) belongs to the series it shortens.
    if (series.ends_with("_tc30")) series.resize(series.size() - 5);
    return "cg1" + series;
  };
  // The figures the study compares as ratios to CG 1 of the same series (the issue: its "0.6 mJ"
  // has no stated normalisation, so ratios are what carries over): kinetic energy, mean and jet
  // speed, collisions per original, dissipated energy in total (per kg reads the same, the mass is
  // 1 g in every case) and per DEM step.
  constexpr std::size_t kCompared = 6;
  std::map<std::string, std::array<double, kCompared>> figures;
  for (const Case* c : present) {
    const tools::Table maps_table =
        no_maps.count(c->name) ? tools::Table{}
                               : table_or_empty(root + "/" + c->name + "/mill_summary.csv");
    const Row maps = first_row(maps_table), cr = row_of(coll, c->name), kr = row_of(ke, c->name);
    const double span = cr("t_to_s") - cr("t_from_s");
    figures[c->name] = {kr("mean"),
                        maps("mean_speed_m_per_s"),
                        maps("jet_mean_speed_m_per_s"),
                        cr("freq_pp_per_original_per_s"),
                        cr("dissipated_J"),
                        cr("dissipated_J") * dem_dt[c->name] / span};
  }
  std::map<std::string, double> wall_ref;
  double rate_prev = std::nan("");
  int n_prev = 0;
  std::string series_prev;
  std::ostringstream table;
  table
      << "case,originals_per_parcel,size_factor,parcels,window_from_s,window_to_s,simulated_s,"
         "kinetic_energy_J,kinetic_energy_err_J,mean_speed_m_per_s,jet_speed_m_per_s,"
         "collision_rate_pp_per_s,collision_rate_pw_per_s,freq_pp_per_original_per_s,"
         "freq_pw_per_original_per_s,rate_pp_change_per_doubling,dissipated_J,"
         "dissipated_normal_damping_J,dissipated_tangential_damping_J,dissipated_sliding_J,"
         "dissipated_rolling_J,dissipation_rate_W,dissipated_per_step_J,dissipated_per_kg_J_per_kg,"
         "outlet_mass_kg,kinetic_energy_vs_cg1,mean_speed_vs_cg1,jet_speed_vs_cg1,"
         "freq_pp_per_original_vs_cg1,dissipated_vs_cg1,dissipated_per_step_vs_cg1,"
         "wall_s_per_simulated_s,speedup_vs_cg1,"
      << kSpeedupColumns << "\n";
  for (const Case* c : present) {
    const std::string dir = root + "/" + c->name;
    const auto [removed, parcels] =
        last_and_max(dir + "/timeseries.csv", "mass_removed_kg", "particles");
    const tools::Table maps_table =
        no_maps.count(c->name) ? tools::Table{} : table_or_empty(dir + "/mill_summary.csv");
    const Row maps = first_row(maps_table), cr = row_of(coll, c->name), kr = row_of(ke, c->name);
    const auto [wall, timed] = read_timing(dir);
    const double wps = wall > 0 && timed > 0 ? wall / timed : std::nan("");
    if (c->n == 1) wall_ref[c->name] = wps;
    const std::string ref = series_ref(c->name);
    const double wall_cg1 = wall_ref.count(ref) ? wall_ref[ref] : std::nan("");
    const double rate_pp = cr("rate_pp_per_s");
    // Change of the particle-particle collision rate per doubling of n from the previous case
    // (the study reports about -60 %): (rate / rate_prev)^(1 / log2(n / n_prev)) - 1.
    // Within a series only (a partly run series may sit next to another in `present`).
    const double per_doubling =
        n_prev > 0 && c->n > n_prev && ref == series_prev
            ? std::pow(rate_pp / rate_prev, 1.0 / std::log2(double(c->n) / n_prev)) - 1
            : std::nan("");
    rate_prev = rate_pp, n_prev = c->n, series_prev = ref;
    const double span = cr("t_to_s") - cr("t_from_s");
    table << c->name << "," << c->n << "," << fmt(std::cbrt(double(c->n))) << ","
          << fmt(parcels, "%.0f") << "," << fmt(from - spin_up) << "," << fmt(end - spin_up) << ","
          << fmt(last_time(dir + "/timeseries.csv") - spin_up) << "," << fmt(kr("mean")) << ","
          << fmt(kr("stderr_mean")) << "," << fmt(maps("mean_speed_m_per_s")) << ","
          << fmt(maps("jet_mean_speed_m_per_s")) << "," << fmt(rate_pp) << ","
          << fmt(cr("rate_pw_per_s")) << "," << fmt(cr("freq_pp_per_original_per_s")) << ","
          << fmt(cr("freq_pw_per_original_per_s")) << "," << fmt(per_doubling) << ","
          << fmt(cr("dissipated_J")) << "," << fmt(cr("dissipated_normal_damping_J")) << ","
          << fmt(cr("dissipated_tangential_damping_J")) << "," << fmt(cr("dissipated_sliding_J"))
          << "," << fmt(cr("dissipated_rolling_J")) << "," << fmt(cr("dissipation_rate_W")) << ","
          << fmt(cr("dissipated_J") * dem_dt[c->name] / span) << ","
          << fmt(cr("dissipated_per_kg_J_per_kg")) << "," << fmt(removed);
    const auto own = figures[c->name];
    const auto ref_fig = figures.find(ref);
    for (std::size_t k = 0; k < kCompared; ++k)
      table << "," << (ref_fig == figures.end() ? std::string() : fmt(own[k] / ref_fig->second[k]));
    table << "," << fmt(wps) << "," << fmt(wall_cg1 / wps);
    // The split against CG 1 of the same series (the parcels fed, not the banner's zero).
    const std::string ref_dir = root + "/" + ref;
    // Only a reference that reached the window's end (a CG 1 still feeding would be compared on
    // its lighter, earlier part).
    const bool ref_present =
        std::any_of(present.begin(), present.end(), [&](const Case* r) { return r->name == ref; });
    const double ref_parcels =
        ref_present
            ? last_and_max(ref_dir + "/timeseries.csv", "mass_removed_kg", "particles").second
            : 0.0;
    table << "," << speedup_columns(dir, ref_parcels > 0 ? ref_dir : "", parcels, ref_parcels)
          << "\n";
  }
  write_file_atomic(root + "/study.csv", table.str());
  std::cout << "jet_mill study table: " << fs::absolute(root + "/study.csv").string() << "\n"
            << table.str();
  return 0;
}

}  // namespace lbdem::studies

#include "studies/rheometer_study.hpp"

#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <utility>

#include "core/config.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/types.hpp"
#include "studies/study_case.hpp"
#include "tools/src/run_comparison.hpp"
#include "scenarios/run_command.hpp"

namespace lbdem::studies {

// A study builds on the scenarios' configs, geometry and run command.
using namespace lbdem::scenarios;

namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name, preset, rule;
  double l;
  std::vector<std::string> sets;
  std::string note;
};

// The series of the rheometer study (docs/studies.md): CG 1 / 1.6 / 2 under the seed's literal rule
// (stiffness_only), linear similarity and Hertz, the fixed-step variants, a t_c/50 check, and the
// geometry variants that test the gap-jamming and blade-resolution explanations.
const std::vector<Case>& cases() {
  static const std::vector<Case> c = {
      {"cg1", "cg1", "seed (l = 1)", 1, {}, "dt 3.6 us"},
      {"cg1_6", "cg1_6", "stiffness_only", 1.6, {}, "dt 3.6 us x l"},
      {"cg2", "cg2", "stiffness_only", 2, {}, "dt 3.6 us x l"},
      {"cg1_6_fixed_dt",
       "cg1_6",
       "stiffness_only",
       1.6,
       {"coarse_grain.scale_dt=false"},
       "dt 3.6 us"},
      {"cg2_fixed_dt", "cg2", "stiffness_only", 2, {"coarse_grain.scale_dt=false"}, "dt 3.6 us"},
      {"cg1_6_similarity", "cg1_6_similarity", "linear_similarity", 1.6, {}, "dt 3.6 us x l"},
      {"cg2_similarity", "cg2_similarity", "linear_similarity", 2, {}, "dt 3.6 us x l"},
      {"cg1_hertz", "cg1_hertz", "hertz (l = 1)", 1, {}, "dt 3.6 us"},
      {"cg1_6_hertz", "cg1_6_hertz", "hertz", 1.6, {}, "dt 3.6 us x l"},
      {"cg2_hertz", "cg2_hertz", "hertz", 2, {}, "dt 3.6 us x l"},
      {"cg1_tc50", "cg1", "seed (l = 1)", 1, {"dem.dt=1.1e-6"}, "dt t_c/50"},
      // t_c = 110 us for the l = 2 parcels under stiffness_only (k x 2, mass x 8): t_c/50.
      {"cg2_tc50",
       "cg2",
       "stiffness_only",
       2,
       {"coarse_grain.scale_dt=false", "dem.dt=2.2e-6"},
       "dt t_c/50"},
      // Explanations of the CG torque change (docs/studies.md, Rheometer). Gap jamming: a 2 mm
      // blade-wall gap is 0.93 parcel diameters at l = 2, as the 1 mm gap is at l = 1; its CG 1
      // reference has the same geometry. Parcels across the blade: a 20 mm blade has 9.3 parcels
      // across its height at l = 2, as the 10 mm blade has at l = 1 (blade top at 30 mm, still
      // under the 39 mm bed).
      {"cg1_gap2", "cg1", "seed (l = 1)", 1, {"rheometer.blade_span=0.046"}, "gap 2 mm"},
      {"cg2_gap2", "cg2", "stiffness_only", 2, {"rheometer.blade_span=0.046"}, "gap 2 mm"},
      {"cg1_tall", "cg1", "seed (l = 1)", 1, {"rheometer.blade_height=0.02"}, "blade 20 mm"},
      {"cg2_tall", "cg2", "stiffness_only", 2, {"rheometer.blade_height=0.02"}, "blade 20 mm"},
  };
  return c;
}

}  // namespace

TorqueSummary summarize_torque(const std::vector<double>& t, const std::vector<double>& q,
                               double start, double rpm) {
  TorqueSummary out;
  const double rev = 60.0 / std::max(std::abs(rpm), 1e-300);
  const auto block_means = [&](double t0, double t1, double width) {
    std::vector<double> sum, n;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k] <= t0 || t[k] > t1) continue;
      const auto b = static_cast<std::size_t>((t[k] - t0) / width);
      if (b >= sum.size()) sum.resize(b + 1, 0.0), n.resize(b + 1, 0.0);
      sum[b] += q[k], n[b] += 1;
    }
    std::vector<double> m;
    for (std::size_t b = 0; b < sum.size(); ++b)
      if (n[b] > 0) m.push_back(sum[b] / n[b]);
    return m;
  };
  for (double m : block_means(start, start + rev, 0.01)) out.peak = std::max(out.peak, m);
  const double t_end = t.empty() ? 0.0 : t.back();
  const auto m = block_means(start + rev, t_end, 0.05);
  double s = 0, s2 = 0, n = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > start + rev) s += q[k], s2 += q[k] * q[k], n += 1;
  if (n > 1) {
    out.steady = s / n;
    out.fluctuation = std::sqrt(std::max(0.0, s2 / n - out.steady * out.steady));
  }
  out.blocks = static_cast<int>(m.size());
  if (m.size() > 1) {
    double mm = 0, v = 0;
    for (double x : m) mm += x / m.size();
    for (double x : m) v += (x - mm) * (x - mm) / (m.size() - 1);
    out.steady_err = std::sqrt(v / m.size());
  }
  return out;
}

int run_rheometer_study(const StudyOptions& opt) {
  std::vector<const Case*> todo;
  std::vector<std::string> names;
  for (const auto& c : cases()) names.push_back(c.name);
  check_case_names(opt.cases, names, "rheometer");
  for (const std::size_t k : cases_to_run(opt.cases, names, std::vector<bool>(names.size(), true)))
    todo.push_back(&cases()[k]);
  const std::string root = opt.out.empty() ? "runs/studies/rheometer" : opt.out;
  fs::create_directories(root);
  const std::string src = LBDEM_SOURCE_DIR;
  std::ostringstream table;
  table << "case,rule,size_factor,note,parcels,gap_parcel_diameters,parcels_across_blade,"
           "peak_torque_Nm,"
           "steady_torque_Nm,steady_torque_err_Nm,fluctuation_Nm,blocks,simulated_s,"
           "wall_s_per_simulated_s,"
        << kSpeedupColumns << "\n";
  for (const Case* c : todo) {
    StudyCase sc{c->name, "rheometer", src + "/scenarios/rheometer/presets/" + c->preset + ".toml",
                 c->sets};
    if (const int rc = run_study_case(root, sc, opt, "rheometer study"); rc != 0) return rc;
  }
  // The table holds every case of the study folder, not only those of this invocation.
  for (const auto& case_ : cases()) {
    const Case* c = &case_;
    const std::string dir = root + "/" + c->name;
    if (!fs::exists(dir + "/config.toml") || !fs::exists(dir + "/timeseries.csv")) continue;
    const Config cfg = Config::from_file(dir + "/config.toml");
    const tools::Table s = tools::read_csv(dir + "/timeseries.csv");
    if (!s.has("time_s") || !s.has("torque_Nm")) continue;
    const double start = cfg.section("rheometer").get("start", 0.2);
    const double rpm = cfg.section("rheometer").get("rpm", 600.0);
    const TorqueSummary ts =
        summarize_torque(s.column("time_s"), s.column("torque_Nm"), start, rpm);
    const double simulated = s.rows() == 0 ? 0.0 : s.column("time_s").back();
    const auto [wall, timed] = read_timing(dir);
    const double l = c->l;
    const double gap = cfg.section("rheometer").get("cup_radius", 0.025) -
                       0.5 * cfg.section("rheometer").get("blade_span", 0.048);
    // Nominal parcel count and size from the fixed original radius of the presets.
    const double r0 = cfg.section("particles").section("radius").get("radius", 5.3655e-4);
    const double rho = cfg.table_array("materials").front().get("density", 950.0);
    const double mass = cfg.section("rheometer").get("fill_mass", 43.6e-3);
    table << c->name << "," << c->rule << "," << l << "," << c->note << ","
          << fmt(std::round(mass / (rho * 4.0 / 3.0 * kPi * std::pow(l * r0, 3))), "%.0f") << ","
          << fmt(gap / (2 * l * r0)) << ","
          << fmt(cfg.section("rheometer").get("blade_height", 0.01) / (2 * l * r0)) << ","
          << fmt(ts.peak) << "," << fmt(ts.steady) << "," << fmt(ts.steady_err) << ","
          << fmt(ts.fluctuation) << "," << ts.blocks << "," << fmt(simulated) << ","
          << (wall > 0 && timed > 0 ? fmt(wall / timed) : std::string(""));
    // Speed-up against the original bed of the same geometry and contact law.
    const std::string ref = root + "/" +
                            (c->name.find("gap2") != std::string::npos    ? "cg1_gap2"
                             : c->name.find("tall") != std::string::npos  ? "cg1_tall"
                             : c->rule.find("hertz") != std::string::npos ? "cg1_hertz"
                                                                          : "cg1");
    table << "," << speedup_columns(dir, fs::exists(ref + "/log.txt") ? ref : "") << "\n";
  }
  write_file_atomic(root + "/study.csv", table.str());
  // Torque overlay and spectra (tools/): the steady window of every case, labelled by case name.
  const std::string python = LBDEM_PYTHON;
  if (!opt.no_plots && !python.empty()) {
    double from = 0;
    for (const Case* c : todo) {
      const Config cfg = Config::from_file(root + "/" + c->name + "/config.toml");
      from = std::max(from, cfg.section("rheometer").get("start", 0.2) +
                                60.0 / std::abs(cfg.section("rheometer").get("rpm", 600.0)));
    }
    try {
      std::vector<tools::RunStats> res;
      for (const Case* c : todo)
        res.push_back(tools::analyse_run(tools::RunFolder::open(root + "/" + c->name), c->name,
                                         {"torque_Nm", from}));
      tools::write_comparison(root + "/torque", "torque_Nm", res);
      write_file_atomic(root + "/torque_stats.txt", tools::comparison_table("torque_Nm", res));
      const std::string plot = shell_quoted(python) + " " +
                               shell_quoted(src + "/tools/compare_runs.py") + " " +
                               shell_quoted(root + "/torque") + " > /dev/null";
      if (std::system(plot.c_str()) != 0)
        std::cerr << "warning: the torque plot failed (" << plot << ")\n";
      else
        std::cout << "torque plot: " << fs::absolute(root + "/torque.png").string() << "\n";
    } catch (const tools::ToolError& e) {
      std::cerr << "warning: no torque comparison: " << e.what() << "\n";
    }
  }
  std::cout << "rheometer study table: " << fs::absolute(root + "/study.csv").string() << "\n"
            << table.str();
  return 0;
}

}  // namespace lbdem::studies

#include "studies/cg_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include <toml++/toml.h>

#include "core/config.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "run/run_manifest.hpp"
#include "scenarios/run_command.hpp"
#include "studies/study_case.hpp"
#include "tools/src/run_comparison.hpp"
#include "tools/src/run_folder.hpp"

namespace lbdem::studies {

namespace fs = std::filesystem;

namespace {

std::string full(double v) {
  return fmt(v, "%.17g");
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : ",") + w;
  return s;
}

struct Level {
  double l;
  std::string name;
  std::vector<std::string> sets;  // the level's own overrides
};

// The user's config with the study's overrides and the level's, as the run command will read it.
Config level_config(const StudyOptions& opt, const Level& lv) {
  Config c = Config::from_file(opt.config);
  for (const auto& s : opt.sets) c.set_override(s);
  if (opt.end_time > 0) c.set_override("run.end_time=" + full(opt.end_time));
  for (const auto& s : lv.sets) c.set_override(s);
  return c;
}

// Checks that need only the config (before any level is built): one line and exit 2 each.
void check_config(const Config& cfg) {
  if (cfg.section("coarse_grain").has("particles_per_parcel"))
    throw InputError("coarse_grain.particles_per_parcel",
                     to_text(cfg.section("coarse_grain").get("particles_per_parcel", 1.0)),
                     "the cg study sets each level's size factor itself",
                     "remove it from the config and give the levels in --levels");
  // A count of parcels is kept at every size factor, so the levels would not hold the same mass:
  // a coarse-graining comparison needs the same system at each level.
  for (const Config& f : cfg.table_array("fill"))
    if (f.get_int("count", 0) > 0)
      throw InputError(f.path("count"), std::to_string(f.get_int("count", 0)),
                       "a fill by count holds the same number of parcels at every level, so l^3 "
                       "times the mass at size factor l",
                       "fill by mass (mass = M [kg]) for a coarse-graining study");
  if (!cfg.table_array("particle").empty())
    throw InputError("particle", "", "explicit particles keep their number at every level",
                     "fill by mass ([[fill]] with mass = M [kg]) for a coarse-graining study");
}

// One observable at one level, over the statistics window.
struct CgStats {
  std::size_t samples = 0;
  double mean = 0, mean_err = 0;                // window mean and its standard error
  double fluctuation = 0, fluctuation_err = 0;  // sample standard deviation and its error
  bool plateau = true;  // both errors reached a blocking plateau (else they may be too small)
};

CgStats summary(const tools::RunStats& r) {
  return {r.m.n,
          r.m.mean,
          r.err.stderr_mean,
          r.m.std,
          r.std_err.stderr_mean,
          r.err.plateau && r.std_err.plateau};
}

// The first key of `want` that `have` lacks or holds otherwise, as "path = value"; empty if there
// is none. run.end_time may differ (a level run further resumes) and so may output keys.
std::string first_difference(const toml::node& want, const toml::node* have,
                             const std::string& path = "") {
  // Values compared as TOML writes them (the same value reads back the same).
  const auto text = [](const toml::node& n) {
    std::ostringstream o;
    o << toml::node_view<const toml::node>{&n};
    return o.str();
  };
  if (const toml::table* t = want.as_table()) {
    const toml::table* h = have ? have->as_table() : nullptr;
    if (!h) return path;
    for (auto&& [key, node] : *t) {
      const std::string sub =
          path.empty() ? std::string(key.str()) : path + "." + std::string(key.str());
      if (sub == "run.end_time" || sub == "output") continue;
      if (auto d = first_difference(node, h->get(key.str()), sub); !d.empty()) return d;
    }
    return "";
  }
  if (const toml::array* a = want.as_array(); a && a->is_array_of_tables()) {
    const toml::array* h = have ? have->as_array() : nullptr;
    if (!h || h->size() != a->size()) return path + " (" + std::to_string(a->size()) + " tables)";
    for (std::size_t k = 0; k < a->size(); ++k)
      if (auto d = first_difference(*a->get(k), h->get(k), path + "[" + std::to_string(k) + "]");
          !d.empty())
        return d;
    return "";
  }
  return have && text(*have) == text(want) ? "" : path + " = " + text(want);
}

}  // namespace

CgDifference cg_difference(double value, double err, double ref, double ref_err, double tolerance) {
  CgDifference d;
  d.diff = value - ref;
  d.rel = ref != 0 ? d.diff / std::abs(ref) : (d.diff == 0 ? 0.0 : std::nan(""));
  const double sigma = std::hypot(err, ref_err);
  // No error (too few samples for blocking): no z and no verdict. Both errors zero (a constant
  // signal): any difference is resolved.
  d.z = std::isnan(sigma) ? sigma
        : sigma > 0       ? d.diff / sigma
        : d.diff == 0     ? 0.0
                          : std::copysign(INFINITY, d.diff);
  if (std::isnan(d.z))
    d.verdict = "";
  else if (std::abs(d.z) <= kCgSigma)
    d.verdict = "same";
  else if (std::abs(d.rel) <= tolerance)
    d.verdict = "close";
  else
    d.verdict = "differs";
  return d;
}

std::string cg_case_name(double l) {
  std::string s = "cg" + fmt(l, "%g");
  std::replace(s.begin(), s.end(), '.', '_');
  return s;
}

std::vector<std::string> cg_default_observables(const std::string& scenario) {
  if (scenario == "fluidized_bed") return {"bed_height_m", "pressure_drop_Pa"};
  if (scenario == "rheometer") return {"torque_Nm"};
  return {"kinetic_energy_J"};
}

int run_cg_study(const StudyOptions& opt) {
  // Every check before anything is written.
  if (opt.config.empty())
    throw InputError("--config", "(none)", "the cg study runs a config of yours at each level",
                     "give --config FILE (a preset, or a run folder's config.toml)");
  if (!fs::is_regular_file(opt.config))
    throw InputError("--config", opt.config, "file not found", "give the path of a TOML file");
  if (!opt.cases.empty())
    throw InputError("--cases", joined(opt.cases), "the cg study's cases are its levels",
                     "give the size factors in --levels, e.g. --levels 1,2,4");
  if (opt.levels.size() < 2)
    throw InputError("--levels", opt.levels.empty() ? "(none)" : fmt(opt.levels[0], "%g"),
                     "a comparison needs at least two size factors",
                     "give e.g. --levels 1,2,4 (the smallest is the reference)");
  std::vector<Level> levels;
  for (const double l : opt.levels) {
    if (!(l >= 1) || !std::isfinite(l))
      throw InputError("--levels", fmt(l, "%g"),
                       "a size factor is at least 1 (a parcel stands for l^3 originals)",
                       "give size factors >= 1, e.g. --levels 1,2,4");
    Level lv{l, cg_case_name(l), {"coarse_grain.size_factor=" + full(l)}};
    if (!opt.rule.empty()) lv.sets.push_back("coarse_grain.rule=" + opt.rule);
    for (const auto& other : levels)
      if (other.name == lv.name)
        throw InputError("--levels", fmt(l, "%g"), "given twice", "give each size factor once");
    levels.push_back(lv);
  }
  const auto check_key = [](const std::string& option, const std::string& s) {
    const std::string key = s.substr(0, s.find('='));
    if (key == "coarse_grain.size_factor" || key == "coarse_grain.particles_per_parcel")
      throw InputError(option, s, "the cg study sets each level's size factor itself",
                       "give the size factors in --levels");
    if (key == "coarse_grain.rule")
      throw InputError(option, s, "the cg study takes the rule as --rule",
                       "give --rule " + s.substr(s.find('=') + 1));
  };
  for (const auto& s : opt.sets) check_key("--set", s);
  // Per-level overrides, "L:key=value", applied after --set (a gas grid that coarsens with the
  // parcels, a skin or an output interval of one level).
  for (const auto& ls : opt.level_sets) {
    const std::size_t colon = ls.find(':');
    const std::string fix = "give L:key=value with L one of --levels, e.g. " +
                            fmt(levels.back().l, "%g") + ":fluid.dx=0.0004";
    if (colon == std::string::npos || ls.find('=', colon) == std::string::npos)
      throw InputError("--level-set", ls, "not of the form L:key=value", fix);
    double l = std::nan("");
    try {
      std::size_t used = 0;
      l = std::stod(ls.substr(0, colon), &used);
      if (used != colon) l = std::nan("");
    } catch (const std::exception&) {
    }
    const std::string set = ls.substr(colon + 1);
    check_key("--level-set", set);
    const std::string key = set.substr(0, set.find('='));
    for (const auto& g : opt.sets)
      if (g.substr(0, g.find('=')) == key)
        throw InputError("--level-set", ls, "sets " + key + ", which --set " + g + " sets too",
                         "give the key in one of them");
    auto it =
        std::find_if(levels.begin(), levels.end(), [&](const Level& lv) { return lv.l == l; });
    if (it == levels.end()) throw InputError("--level-set", ls, "names no level of --levels", fix);
    it->sets.push_back(set);
  }
  const double tolerance = std::isnan(opt.tolerance) ? kCgTolerance : opt.tolerance;
  if (!(tolerance >= 0))
    throw InputError("--tolerance", fmt(opt.tolerance, "%g"), "a relative difference is at least 0",
                     "give e.g. --tolerance 0.05 (5 %)");
  const Config base = level_config(opt, levels.front());
  const std::string scenario = base.get_string("scenario", "");
  if (scenario.empty())
    throw InputError(
        "scenario", "(none)", "the config names no scenario",
        "write scenario = \"...\" at the top of " + opt.config + " (./lbdem run --list)");
  check_config(base);
  const double end_time = base.section("run").get("end_time", 0.0);
  const double from = opt.window_from > 0 ? opt.window_from : 0.5 * end_time;
  const double to = opt.window_to > 0 ? opt.window_to : end_time;
  if (!(from < end_time))
    throw InputError(
        "--from", fmt(from, "%g"),
        "the window starts at or after the runs' end, run.end_time = " + fmt(end_time, "%g") + " s",
        "give --from below it, or a later --end-time");
  const std::vector<std::string> observables =
      opt.observables.empty() ? cg_default_observables(scenario) : opt.observables;

  // The coarsest level first: the cheapest, so the first result and any late error come early.
  std::vector<std::size_t> order(levels.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return levels[a].l > levels[b].l; });
  const std::string root = opt.out.empty() ? "runs/studies/cg" : opt.out;

  // Each level is read as the run command will read it (a rule that refuses the contact law, a
  // grid that a level's kernel does not fit), and the observables are checked against the columns
  // its run will write, before any level runs.
  std::vector<std::string> columns;
  for (const std::size_t k : order) {
    if (opt.no_run) break;  // compare what the folder holds
    const Level& lv = levels[k];
    const std::string dir = root + "/" + lv.name;
    const Config cfg = level_config(opt, lv);
    try {
      columns = scenarios::read_as_scenario(scenario, cfg);
    } catch (const InputError& e) {
      throw InputError(e.key(), e.value(), e.problem() + " (at level l = " + fmt(lv.l, "%g") + ")",
                       e.fix());
    }
    if (!fs::exists(dir + "/config.toml")) continue;
    // A level already in the folder resumes: it must be a run of this config as read now, every
    // default included, not another config's left in the same --out (the default folder is
    // shared).
    const toml::table want = toml::parse(cfg.resolved_toml());
    const toml::table have = toml::parse_file(dir + "/config.toml");
    std::string d = first_difference(want, &have);
    if (d.empty()) d = first_difference(have, &want);
    if (!d.empty())
      throw InputError("--out", root,
                       "its " + lv.name + " is a run of another config (" + d +
                           " in one of the two, not in the other)",
                       "give another --out for this config, or remove " + dir);
  }
  if (columns.empty() && opt.no_run)
    for (const auto& lv : levels)
      if (fs::exists(root + "/" + lv.name + "/timeseries.csv")) {
        columns = tools::read_csv(root + "/" + lv.name + "/timeseries.csv").names;
        break;
      }
  if (!columns.empty())
    for (const auto& o : observables)
      if (std::find(columns.begin(), columns.end(), o) == columns.end())
        throw InputError(
            opt.observables.empty() ? "scenario" : "--observables", o,
            "not a timeseries.csv column of this " + scenario + " run",
            "did you mean '" + nearest(o, columns) + "'? (its columns: " + joined(columns) + ")");

  fs::create_directories(root);
  for (const std::size_t k : order) {
    const Level& lv = levels[k];
    const StudyCase c{lv.name, scenario, opt.config, lv.sets};
    if (const int rc = run_study_case(root, c, opt, "cg study"); rc != 0) return rc;
  }

  // The comparison: the finest level that has rows in the window is the reference.
  struct Result {
    const Level* level;
    std::string dir;
    double simulated = 0;
    std::vector<tools::RunStats> stats;  // per observable; empty: not enough rows
    std::string why;                     // why there are none
  };
  std::vector<Result> results;
  std::vector<std::size_t> finest_first = order;
  std::reverse(finest_first.begin(), finest_first.end());
  for (const std::size_t k : finest_first) {
    Result r{&levels[k], root + "/" + levels[k].name, 0, {}, ""};
    if (!fs::exists(r.dir + "/timeseries.csv")) continue;
    const tools::RunFolder run = tools::RunFolder::open(r.dir);
    if (run.series.rows() == 0) continue;
    r.simulated = run.time().back();
    // The same statistics as lbdem-compare-runs (rows resampled where unevenly spaced); a window
    // with too few rows, or an observable the run lacks, leaves the level without statistics.
    try {
      for (const auto& o : observables)
        r.stats.push_back(tools::analyse_run(run, r.level->name, {o, from, to}));
    } catch (const tools::ToolError& e) {
      r.stats.clear();
      r.why = e.what();
    }
    results.push_back(std::move(r));
  }
  const Result* ref = nullptr;
  for (const auto& r : results)
    if (!r.stats.empty()) {
      ref = &r;
      break;
    }

  std::ostringstream lv_csv, ob_csv, text;
  lv_csv << "case,size_factor,parcels,simulated_s,wall_s_per_simulated_s," << kSpeedupColumns
         << "\n";
  ob_csv << "observable,case,size_factor,window_from_s,window_to_s,samples,mean,mean_err,"
            "fluctuation,fluctuation_err,error_plateau,mean_diff,mean_rel_diff,mean_z,"
            "mean_verdict,fluctuation_diff,fluctuation_rel_diff,fluctuation_z,"
            "fluctuation_verdict\n";
  const std::string rule =
      !opt.rule.empty() ? opt.rule
                        : base.section("coarse_grain").get_string("rule", "(the default rule)");
  text << "coarse-graining report: " << opt.config << " (" << scenario << "), rule " << rule
       << ", window " << fmt(from, "%g") << "-" << fmt(to, "%g") << " s\n";
  text << "reference: "
       << (ref ? ref->level->name + " (l = " + fmt(ref->level->l, "%g") + ")"
               : std::string("none yet (no level has rows in the window)"))
       << "; verdicts: same = |z| <= " << fmt(kCgSigma, "%g")
       << " (no difference the statistics resolve), close = resolved but within "
       << fmt(100 * tolerance, "%g") << " %, differs = neither\n";
  for (const auto& ls : opt.level_sets) text << "level override: " << ls << "\n";
  text << "\n";
  text << "level     parcels   simulated s   wall s per simulated s   speed-up\n";
  for (const auto& r : results) {
    double parcels = std::nan("");
    if (const auto m = run::read_run_manifest(r.dir)) parcels = m->number("particles");
    const PartCosts cost = part_costs(r.dir);
    lv_csv << r.level->name << "," << fmt(r.level->l, "%g") << "," << fmt(parcels, "%.0f") << ","
           << fmt(r.simulated) << "," << (cost.total > 0 ? fmt(cost.total) : "") << ","
           << speedup_columns(r.dir, ref ? ref->dir : std::string()) << "\n";
    const PartCosts ref_cost = ref ? part_costs(ref->dir) : PartCosts{};
    char line[160];
    std::snprintf(
        line, sizeof line, "%-8s %9s %13s %24s %10s\n", r.level->name.c_str(),
        fmt(parcels, "%.0f").c_str(), fmt(r.simulated).c_str(),
        cost.total > 0 ? fmt(cost.total).c_str() : "-",
        cost.total > 0 && ref_cost.total > 0 ? fmt(ref_cost.total / cost.total).c_str() : "-");
    text << line;
  }
  for (std::size_t o = 0; o < observables.size(); ++o) {
    text << "\n"
         << observables[o]
         << "\nlevel     samples   mean +- error             fluctuation +- error     "
            "mean vs ref (rel, z)          fluctuation vs ref (rel, z)\n";
    for (const auto& r : results) {
      if (r.stats.empty()) {
        text << r.level->name << "  (no statistics: " << r.why << ")\n";
        continue;
      }
      const CgStats s = summary(r.stats[o]);
      ob_csv << observables[o] << "," << r.level->name << "," << fmt(r.level->l, "%g") << ","
             << fmt(from, "%g") << "," << fmt(to, "%g") << "," << s.samples << "," << fmt(s.mean)
             << "," << fmt(s.mean_err) << "," << fmt(s.fluctuation) << "," << fmt(s.fluctuation_err)
             << "," << (s.plateau ? "yes" : "no");
      std::string vs_mean = "reference", vs_fluct = "reference";
      if (ref && &r != ref) {
        const CgStats q = summary(ref->stats[o]);
        const CgDifference dm = cg_difference(s.mean, s.mean_err, q.mean, q.mean_err, tolerance);
        const CgDifference df = cg_difference(s.fluctuation, s.fluctuation_err, q.fluctuation,
                                              q.fluctuation_err, tolerance);
        ob_csv << "," << fmt(dm.diff) << "," << fmt(dm.rel) << "," << fmt(dm.z) << "," << dm.verdict
               << "," << fmt(df.diff) << "," << fmt(df.rel) << "," << fmt(df.z) << "," << df.verdict
               << "\n";
        const auto vs = [](const CgDifference& d) {
          return (d.verdict.empty() ? std::string("no error") : d.verdict) + " (" +
                 fmt(100 * d.rel, "%+.3g") + " %, " + fmt(d.z, "%+.2g") + ")";
        };
        vs_mean = vs(dm), vs_fluct = vs(df);
      } else {
        ob_csv << ",,,,,,,,\n";
      }
      char line[256];
      std::snprintf(line, sizeof line, "%-8s %8zu   %-24s %-24s %-29s %s%s\n",
                    r.level->name.c_str(), s.samples,
                    (fmt(s.mean) + " +- " + fmt(s.mean_err)).c_str(),
                    (fmt(s.fluctuation) + " +- " + fmt(s.fluctuation_err)).c_str(), vs_mean.c_str(),
                    vs_fluct.c_str(),
                    s.plateau ? "" : "  [errors without a blocking plateau: may be too small]");
      text << line;
    }
  }
  write_file_atomic(root + "/cg_levels.csv", lv_csv.str());
  write_file_atomic(root + "/cg_observables.csv", ob_csv.str());
  write_file_atomic(root + "/cg_report.txt", text.str());
  std::cout << text.str() << "\ntables: " << fs::absolute(root + "/cg_levels.csv").string() << ", "
            << fs::absolute(root + "/cg_observables.csv").string() << "\n";
  // Per observable, the series and spectra of every level with statistics, as lbdem-compare-runs
  // writes them (ROOT/OBSERVABLE_stats.csv, _spectra.csv), and their figure
  // (tools/compare_runs.py).
  const std::string python = LBDEM_PYTHON;
  for (std::size_t o = 0; o < observables.size(); ++o) {
    std::vector<tools::RunStats> series;
    for (const auto& r : results)
      if (!r.stats.empty()) series.push_back(r.stats[o]);
    if (series.empty()) continue;
    const std::string prefix = root + "/" + observables[o];
    tools::write_comparison(prefix, observables[o], series);
    if (opt.no_plots || python.empty()) continue;
    const std::string plot =
        shell_quoted(python) + " " +
        shell_quoted(std::string(LBDEM_SOURCE_DIR) + "/tools/compare_runs.py") + " " +
        shell_quoted(prefix) + " > /dev/null";
    if (std::system(plot.c_str()) != 0)
      std::cerr << "warning: the plot failed (" << plot << ")\n";
    else
      std::cout << "plot: " << fs::absolute(prefix + ".png").string() << "\n";
  }
  return 0;
}

}  // namespace lbdem::studies

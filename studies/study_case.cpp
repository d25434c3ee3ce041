#include "studies/study_case.hpp"

#include "run/run_manifest.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "core/config.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/run_clock.hpp"
#include "run/checkpoint_check.hpp"
#include "run/run_cost.hpp"
#include "run/run_manifest.hpp"
#include "scenarios/run_command.hpp"

namespace lbdem::studies {

// A study builds on the scenarios' configs, geometry and run command.
using namespace lbdem::scenarios;
using namespace lbdem::run;

namespace fs = std::filesystem;

namespace {

std::string status_of(const std::string& dir) {
  std::ifstream f(dir + "/status");
  std::string s;
  std::getline(f, s);
  return s;
}

std::string full(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

void check_case_names(const std::vector<std::string>& wanted, const std::vector<std::string>& known,
                      const std::string& study) {
  for (const auto& want : wanted)
    if (std::find(known.begin(), known.end(), want) == known.end())
      throw InputError("--cases", want, "no such " + study + " case",
                       "did you mean '" + nearest(want, known) + "'? (./lbdem study --list)");
}

std::vector<std::size_t> cases_to_run(const std::vector<std::string>& wanted,
                                      const std::vector<std::string>& known,
                                      const std::vector<bool>& by_default) {
  std::vector<std::size_t> out;
  if (wanted.empty()) {
    for (std::size_t k = 0; k < known.size(); ++k)
      if (by_default[k]) out.push_back(k);
    return out;
  }
  for (const auto& w : wanted) {
    const auto k = std::size_t(std::find(known.begin(), known.end(), w) - known.begin());
    if (k < known.size() && std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

double last_time(const std::string& csv) {
  std::ifstream f(csv);
  std::string line, last;
  if (!std::getline(f, line)) return 0.0;  // header
  while (std::getline(f, line))
    if (!line.empty()) last = line;
  if (last.empty()) return 0.0;
  try {
    return std::stod(last.substr(0, last.find(',')));  // time_s is the first column
  } catch (const std::exception&) {
    return 0.0;
  }
}

std::pair<double, double> read_timing(const std::string& dir) {
  std::ifstream in(dir + "/study_timing.txt");
  double wall = 0, simulated = 0;
  if (!(in >> wall >> simulated)) return {0.0, 0.0};
  return {wall, simulated};
}

double timed_from(const std::string& dir) {
  std::ifstream in(dir + "/study_timing.txt");
  double wall = 0, simulated = 0, from = 0;
  if (!(in >> wall >> simulated >> from)) return std::nan("");
  return from;
}

std::vector<std::pair<std::string, double>> read_phase_table(const std::string& log,
                                                             std::streamoff from) {
  std::ifstream in(log);
  if (from > 0) in.seekg(from);
  std::vector<std::pair<std::string, double>> table, current;
  bool on = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("wall time by phase", 0) == 0) {
      on = true;
      current.clear();
      continue;
    }
    if (!on) continue;
    // "  gas: stream-collide      823.731 s   29.1 %": name, seconds, "s", share, "%".
    std::istringstream ls(line);
    std::vector<std::string> w;
    for (std::string t; ls >> t;) w.push_back(t);
    if (line.rfind("  ", 0) != 0 || w.size() < 5 || w[w.size() - 1] != "%" ||
        w[w.size() - 3] != "s") {
      on = false;
      if (!current.empty()) table = current;
      continue;
    }
    const std::size_t end = line.find(w[w.size() - 4], 2);
    std::string name = line.substr(2, end - 2);
    name.erase(name.find_last_not_of(' ') + 1);
    try {
      current.emplace_back(name, std::stod(w[w.size() - 4]));
    } catch (const std::exception&) {
      on = false;
    }
  }
  if (on && !current.empty()) table = current;
  return table;
}

std::vector<std::pair<std::string, double>> read_phase_sums(const std::string& dir) {
  std::vector<std::pair<std::string, double>> out;
  std::ifstream in(dir + "/study_phases.txt");
  for (std::string line; std::getline(in, line);) {
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos) continue;
    try {
      out.emplace_back(line.substr(tab + 1), std::stod(line.substr(0, tab)));
    } catch (const std::exception&) {
    }
  }
  return out;
}

namespace {

// Groups of the phase timers (core/phase_timer.cpp names them "gas: ...", "DEM: ...",
// "coupling: ...").
void add_phase(PartCosts& p, const std::string& name, double seconds) {
  if (name.rfind("gas:", 0) == 0)
    p.gas += seconds;
  else if (name.rfind("DEM:", 0) == 0)
    p.dem += seconds;
  else if (name.rfind("coupling:", 0) == 0)
    p.coupling += seconds;
  else
    p.rest += seconds;
}

}  // namespace

PartCosts part_costs(const std::string& dir) {
  PartCosts p;
  // The run's manifest (run.toml) holds its checkpoint's sums; a folder written before lbdem kept
  // one has the study's own files (study_timing.txt, study_phases.txt).
  const auto manifest = read_run_manifest(dir);
  const RunCost* cost = manifest && manifest->cost ? &*manifest->cost : nullptr;
  const auto [wall, simulated] =
      cost ? std::pair{cost->wall_s, cost->to_s - cost->from_s} : read_timing(dir);
  if (!(wall > 0 && simulated > 0)) return p;
  p.total = wall / simulated;
  double sum = 0;
  for (const auto& [name, sec] : cost ? cost->phases : read_phase_sums(dir)) {
    add_phase(p, name, sec);
    sum += sec;
  }
  // Summed phases: each part's own seconds per simulated second; the rest is everything else of
  // the wall time (output, steering and, in sums the study kept, set-up, banner and plots).
  double scale = 1.0 / simulated;
  if (!(sum > 0)) {
    // No sums kept: the last invocation's shares of the summed wall time.
    for (const auto& [name, sec] : read_phase_table(dir + "/log.txt")) {
      add_phase(p, name, sec);
      sum += sec;
    }
    if (!(sum > 0)) return p;
    p.from_shares = true;
    scale = p.total / sum;
  }
  p.gas *= scale;
  p.dem *= scale;
  p.coupling *= scale;
  p.rest = p.total - p.gas - p.dem - p.coupling;
  p.split = true;
  return p;
}

double banner_number(const std::string& log, const std::string& key, bool after_equals) {
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  " + key, 0) != 0) continue;
    std::string rest = line.substr(2 + key.size());
    if (after_equals) {
      const std::size_t eq = rest.find("= ");
      if (eq == std::string::npos) return 0.0;
      rest = rest.substr(eq + 2);
    }
    std::istringstream ls(rest);
    double v = 0;
    return (ls >> v) ? v : 0.0;
  }
  return 0.0;
}

std::string speedup_columns(const std::string& dir, const std::string& ref_dir, double parcels,
                            double parcels_ref) {
  auto num = [](double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.4g", v);
    return std::string(b);
  };
  const PartCosts p = part_costs(dir);
  std::string out;
  if (p.split)
    out = num(p.gas) + "," + num(p.dem) + "," + num(p.coupling);
  else
    out = ",,";
  const PartCosts r = ref_dir.empty() ? PartCosts{} : part_costs(ref_dir);
  // A banner number from the run's manifest, or from its log where it has none (folders written
  // before lbdem kept one).
  const auto banner = [](const std::string& d, const std::string& key, const std::string& old_key,
                         bool after_equals) {
    if (d.empty()) return 0.0;
    if (const auto m = read_run_manifest(d)) {
      const double v = m->number(key);
      return std::isnan(v) ? 0.0 : v;
    }
    return banner_number(d + "/log.txt", old_key, after_equals);
  };
  auto ratio = [&](double a, double b) { return a > 0 && b > 0 ? num(a / b) : std::string(); };
  out += "," + ratio(r.total, p.total);
  const double n = parcels > 0 ? parcels : banner(dir, "particles", "particles", false);
  const double n_ref =
      parcels_ref > 0 ? parcels_ref : banner(ref_dir, "particles", "particles", false);
  const double dt = banner(dir, "time step dt", "time step dt", false),
               dt_ref = banner(ref_dir, "time step dt", "time step dt", false);
  const bool split = p.split && r.split;
  out += "," + (split ? ratio(r.dem, p.dem) : std::string()) + "," +
         (r.total > 0 ? ratio(n_ref * dt, n * dt_ref) : std::string());
  const double cells = banner(dir, "gas cells", "cells per axis", true),
               cells_ref = banner(ref_dir, "gas cells", "cells per axis", true);
  const double gdt = banner(dir, "gas time step dt", "gas time step dt", false),
               gdt_ref = banner(ref_dir, "gas time step dt", "gas time step dt", false);
  out += "," + (split && r.gas > 0 ? ratio(r.gas, p.gas) : std::string()) + "," +
         (r.total > 0 ? ratio(cells_ref * gdt, cells * gdt_ref) : std::string());
  std::string bound;
  if (p.split) {
    const double top = std::max({p.gas, p.dem, p.coupling});
    bound = top == p.gas ? "gas" : top == p.dem ? "DEM" : "exchange";
  }
  const double from = timed_from(dir);
  return out + "," + bound + "," + (std::isnan(from) ? std::string() : num(from));
}

std::string fmt(double v, const char* format) {
  if (!std::isfinite(v)) return "";
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

int run_study_case(const std::string& root, const StudyCase& c, const StudyOptions& opt,
                   const std::string& banner) {
  const std::string dir = root + "/" + c.name;
  if (opt.no_run) return 0;  // compare what the folder holds
  const std::string st = status_of(dir);
  RunOptions ro;
  ro.threads = opt.threads;
  ro.no_plots = opt.no_plots;
  if (opt.end_time > 0) ro.sets.push_back("run.end_time=" + full(opt.end_time));
  const double t_before = last_time(dir + "/timeseries.csv");
  const bool finished = st.rfind("finished", 0) == 0;
  const bool resumable = fs::exists(dir + "/checkpoint.h5") && !finished;
  // Done: finished, and (with --end-time) its last row within one output interval of the end.
  double interval = 0;
  if (fs::exists(dir + "/config.toml"))
    interval = Config::from_file(dir + "/config.toml").section("output").get("interval", 0.0);
  if (finished && (opt.end_time <= 0 || t_before >= opt.end_time - interval * (1 + 1e-9))) return 0;
  // Where a resumed run starts: its checkpoint, not the last row of timeseries.csv (a run killed
  // after its last checkpoint left rows beyond it, which the resumed run simulates again).
  double t_start = t_before;
  if (resumable || finished) {
    ro.resume = dir;
    try {
      t_start = checkpoint_time(H5In(dir + "/checkpoint.h5"));
    } catch (const std::exception&) {
      t_start = t_before;  // no checkpoint to read: run_scenario reports why
    }
  } else {
    fs::remove_all(dir);
    ro.scenario = c.scenario;
    ro.config = c.preset;
    ro.out = dir;
    for (const auto& s : c.sets) ro.sets.push_back(s);
    for (const auto& s : opt.sets) ro.sets.push_back(s);
  }
  std::cout << "== " << banner << ": " << c.name << (ro.resume.empty() ? "" : " (resumed)") << "\n";
  // The log grows by this invocation's lines; its phase table is the one after this offset.
  std::streamoff log_before = 0;
  if (!ro.resume.empty() && fs::exists(dir + "/log.txt"))
    log_before = std::streamoff(fs::file_size(dir + "/log.txt"));
  const auto t0 = RunClock::now();
  const int rc = run_scenario(ro);
  const double wall = std::chrono::duration<double>(RunClock::now() - t0).count();
  // A stopped run (130: a signal, checkpoint written) still adds its wall time to the case's.
  if (rc != 0 && rc != 130) return rc;
  // Sums the run keeps in its checkpoint (run_cost.hpp) cover every invocation, a killed one up
  // to its last checkpoint; they replace the sums below, which miss the invocations that never
  // returned here. They time the stepping loop only (the sums below also held set-up, banner and
  // plots), and begin where the checkpoint's sums begin: a case timed here before, whose
  // checkpoint has none, is from then on timed from its first resume by this lbdem (a third
  // number in study_timing.txt; timed_from).
  if (const auto cost = read_run_cost(dir + "/checkpoint.h5")) {
    write_file_atomic(dir + "/study_timing.txt", full(cost->wall_s) + " " +
                                                     full(cost->to_s - cost->from_s) + " " +
                                                     full(cost->from_s) + "\n");
    std::string text;
    for (const auto& [name, sec] : cost->phases) text += full(sec) + "\t" + name + "\n";
    write_file_atomic(dir + "/study_phases.txt", text);
    return rc;
  }
  const double t_after = last_time(dir + "/timeseries.csv");
  const auto [wall0, sim0] = read_timing(dir);
  write_file_atomic(
      dir + "/study_timing.txt",
      full(wall0 + wall) + " " + full(sim0 + t_after - (ro.resume.empty() ? 0.0 : t_start)) + "\n");
  // Phase seconds summed over the invocations, kept only while every invocation left its table
  // (an earlier one without it, or a run killed before it wrote one, ends the sums: part_costs
  // then falls back on shares).
  const auto phases = read_phase_table(dir + "/log.txt", log_before);
  const bool first = ro.resume.empty() || (wall0 == 0 && !fs::exists(dir + "/study_phases.txt"));
  const bool kept = fs::exists(dir + "/study_phases.txt");
  if (!phases.empty() && (first || kept)) {
    std::map<std::string, double> sums;
    std::vector<std::string> order;
    for (const auto& [name, sec] : read_phase_sums(dir)) {
      if (!sums.count(name)) order.push_back(name);
      sums[name] += sec;
    }
    for (const auto& [name, sec] : phases) {
      if (!sums.count(name)) order.push_back(name);
      sums[name] += sec;
    }
    std::string text;
    for (const auto& name : order) text += full(sums[name]) + "\t" + name + "\n";
    write_file_atomic(dir + "/study_phases.txt", text);
  } else if (kept) {
    fs::remove(dir + "/study_phases.txt");
  }
  return rc;
}

}  // namespace lbdem::studies

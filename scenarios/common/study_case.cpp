#include "scenarios/common/study_case.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/config.hpp"
#include "core/error.hpp"
#include "core/h5.hpp"
#include "scenarios/run_command.hpp"

namespace lbdem::scenarios {

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

int run_study_case(const std::string& root, const StudyCase& c, const StudyOptions& opt,
                   const std::string& banner) {
  const std::string dir = root + "/" + c.name;
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
  if (resumable || finished) {
    ro.resume = dir;
  } else {
    fs::remove_all(dir);
    ro.scenario = c.scenario;
    ro.config = c.preset;
    ro.out = dir;
    for (const auto& s : c.sets) ro.sets.push_back(s);
    for (const auto& s : opt.sets) ro.sets.push_back(s);
  }
  std::cout << "== " << banner << ": " << c.name << (ro.resume.empty() ? "" : " (resumed)") << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = run_scenario(ro);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // A stopped run (130: a signal, checkpoint written) still adds its wall time to the case's.
  if (rc != 0 && rc != 130) return rc;
  const double t_after = last_time(dir + "/timeseries.csv");
  const auto [wall0, sim0] = read_timing(dir);
  write_file_atomic(dir + "/study_timing.txt",
                    full(wall0 + wall) + " " +
                        full(sim0 + t_after - (ro.resume.empty() ? 0.0 : t_before)) + "\n");
  return rc;
}

}  // namespace lbdem::scenarios

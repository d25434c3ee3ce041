#include "studies/validation_study.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/h5.hpp"
#include "studies/study_case.hpp"
#include "tools/src/run_folder.hpp"

namespace lbdem::studies {

namespace fs = std::filesystem;

namespace {

struct ValidationCase {
  std::string name, experiment, preset, tool;
  std::vector<std::string> sets;
  double from;  // [s] start of the compared window: the bubbling bed after its inflow ramp
};

// The Mueller bed's side faces as free-slip gas walls (docs/physics.md, Gas boundaries).
std::vector<std::string> free_slip(std::vector<std::string> more = {}) {
  std::vector<std::string> s = {"fluid.faces.x_lo=\"free_slip\"", "fluid.faces.x_hi=\"free_slip\"",
                                "fluid.faces.y_lo=\"free_slip\"", "fluid.faces.y_hi=\"free_slip\""};
  s.insert(s.end(), more.begin(), more.end());
  return s;
}

// Coarse-grained parcels poured from the whole box height: random sequential placement of the
// same 8.36 g as 1.8-2.4 mm parcels needs more room than the preset's 90 mm fill region (27-30 %
// solid there, near what random placement reaches); the settled bed is the same mass.
std::vector<std::string> coarse(std::vector<std::string> more) {
  more.push_back("fill[0].hi=[0.044, 0.01, 0.12]");
  return more;
}

const std::vector<ValidationCase>& cases() {
  static const std::vector<ValidationCase> c = {
      {"mueller_u09",
       "Mueller et al. 2008/2009, U = 0.9 m/s, no-slip gas walls",
       "mueller_u09",
       "mueller_bed.py",
       {},
       0.5},
      {"mueller_u09_slip", "Mueller et al. 2008/2009, U = 0.9 m/s, free-slip gas walls",
       "mueller_u09", "mueller_bed.py", free_slip(), 0.5},
      {"vanwachem2001",
       "van Wachem et al. 2001, U = 0.9 m/s",
       "vanwachem2001",
       "vanwachem_bed.py",
       {},
       1.5},
      {"mueller_u09_slip_cg1p5", "Mueller et al., free-slip gas walls, CG l = 1.5", "mueller_u09",
       "mueller_bed.py", free_slip(coarse({"coarse_grain.size_factor=1.5"})), 0.5},
      {"mueller_u09_slip_cg2", "Mueller et al., free-slip gas walls, CG l = 2", "mueller_u09",
       "mueller_bed.py", free_slip(coarse({"coarse_grain.size_factor=2"})), 0.5},
  };
  return c;
}

// The columns of a case's goals.csv (tools/bed_compare.py), which the study's table repeats.
const std::vector<std::string> kGoalColumns = {"quantity",   "unit", "measured",   "lbdem",
                                               "difference", "goal", "within_goal"};

}  // namespace

int run_validation_study(const StudyOptions& opt) {
  const std::string python = LBDEM_PYTHON;
  if (python.empty())
    throw InputError("LBDEM_PYTHON", "(none)",
                     "the validation study compares with python3 and numpy, h5py, matplotlib",
                     "install them (Debian: python3-numpy python3-h5py python3-matplotlib) and "
                     "reconfigure");
  std::vector<std::string> names;
  for (const auto& c : cases()) names.push_back(c.name);
  check_case_names(opt.cases, names, "validation");
  const std::string root = opt.out.empty() ? "runs/studies/validation" : opt.out;
  fs::create_directories(root);
  const std::string src = LBDEM_SOURCE_DIR;
  for (const std::size_t k :
       cases_to_run(opt.cases, names, std::vector<bool>(names.size(), true))) {
    const ValidationCase& c = cases()[k];
    const StudyCase sc{c.name, "fluidized_bed",
                       src + "/scenarios/fluidized_bed/presets/" + c.preset + ".toml", c.sets};
    if (const int rc = run_study_case(root, sc, opt, "validation study"); rc != 0) return rc;
  }

  // Every case of the folder that has reached its window, compared with its measurements.
  std::ostringstream table;
  table << "case,experiment,quantity,unit,measured,lbdem,difference,goal,within_goal\n";
  int met = 0, goals = 0;
  for (const auto& c : cases()) {
    const std::string dir = root + "/" + c.name;
    if (last_time(dir + "/timeseries.csv") <= c.from) continue;
    std::string cmd = shell_quoted(python) + " " + shell_quoted(src + "/tools/" + c.tool) + " " +
                      shell_quoted(dir) + " --from " + std::to_string(c.from) + " --csv " +
                      shell_quoted(dir + "/goals.csv");
    if (!opt.no_plots) cmd += " --png " + shell_quoted(dir + "/comparison.png");
    cmd += " > " + shell_quoted(dir + "/comparison.txt");
    if (std::system(cmd.c_str()) != 0) {
      std::cerr << "warning: the comparison of " << c.name << " failed (" << cmd << ")\n";
      continue;
    }
    const tools::Table goal = tools::read_csv(dir + "/goals.csv", true);
    for (std::size_t r = 0; r < goal.rows(); ++r) {
      table << tools::csv_field(c.name) << "," << tools::csv_field(c.experiment);
      for (const auto& col : kGoalColumns) table << "," << tools::csv_field(goal.cell(col, r));
      table << "\n";
      const std::string& w = goal.cell("within_goal", r);
      goals += w != "-";
      met += w == "yes";
    }
    if (!opt.no_plots)
      std::cout << "figure: " << fs::absolute(dir + "/comparison.png").string() << "\n";
  }
  write_file_atomic(root + "/validation.csv", table.str());
  std::cout << "validation study table: " << fs::absolute(root + "/validation.csv").string() << "\n"
            << table.str() << met << " of " << goals << " goals met\n";
  return 0;
}

}  // namespace lbdem::studies

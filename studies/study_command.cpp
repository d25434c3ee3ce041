#include "studies/study_command.hpp"

#include <cmath>
#include <iostream>

#include "core/error.hpp"
#include "studies/cg_study.hpp"
#include "studies/fluidized_bed_study.hpp"
#include "studies/jet_mill_study.hpp"
#include "studies/rheometer_study.hpp"
#include "studies/validation_study.hpp"

namespace lbdem::studies {

int run_study(const StudyOptions& opt) {
  if (opt.list || opt.name.empty()) {
    std::cout << "fluidized_bed  original against CG 1-4 beds, cohesionless and cohesive under the "
                 "l^2 and l^3 rules: bed height and pressure drop, spectra, table\n";
    std::cout << "rheometer  CG 1 / 1.6 / 2 of the powder rheometer under each scaling rule: "
                 "torque table and plot\n";
    std::cout << "validation  published bubbling beds (Mueller et al. with no-slip and free-slip "
                 "gas walls and at CG 1.5 and 2, van Wachem et al.) against their measurements: "
                 "goals table and figures\n";
    std::cout << "jet_mill  CG-1, 2, 4, 8, 10 of the spiral jet mill, scaled gas cells "
                 "(cg*_fixed: one grid): maps, profiles, kinetic energy, collisions, table; "
                 "--quick: a check in minutes\n";
    std::cout << "cg  any config at several size factors (--config FILE --levels 1,2,4): each "
                 "observable's mean and fluctuation against the finest level with statistical "
                 "errors, wall time and speed-up\n";
    return 0;
  }
  if (opt.quick && opt.name != "jet_mill")
    throw InputError("--quick", "", "only the jet_mill study has a quick form",
                     "run ./lbdem study " + opt.name + " --end-time T for a short window");
  if ((opt.window_from > 0 || opt.window_to > 0) && opt.name != "fluidized_bed" && opt.name != "cg")
    throw InputError(opt.window_from > 0 ? "--from" : "--to",
                     to_text(opt.window_from > 0 ? opt.window_from : opt.window_to),
                     "only the fluidized_bed and cg studies take a window (the " + opt.name +
                         " study's is the seed study's)",
                     "leave it out");
  if (opt.name != "cg") {
    const char* cg_only = !opt.config.empty()          ? "--config"
                          : !opt.levels.empty()        ? "--levels"
                          : !opt.observables.empty()   ? "--observables"
                          : !opt.rule.empty()          ? "--rule"
                          : !std::isnan(opt.tolerance) ? "--tolerance"
                                                       : nullptr;
    if (cg_only)
      throw InputError(
          cg_only, "",
          "only the cg study takes it (the " + opt.name + " study runs its own presets)",
          "leave it out, or run ./lbdem study cg --config FILE --levels 1,2,4");
  }
  if (opt.window_from > 0 && opt.window_to > 0 && opt.window_to <= opt.window_from)
    throw InputError("--to", to_text(opt.window_to), "the window ends before it starts",
                     "give --to above --from (" + to_text(opt.window_from) + " s)");
  if (opt.name == "rheometer") return run_rheometer_study(opt);
  if (opt.name == "fluidized_bed") return run_fluidized_bed_study(opt);
  if (opt.name == "jet_mill") return run_jet_mill_study(opt);
  if (opt.name == "validation") return run_validation_study(opt);
  if (opt.name == "cg") return run_cg_study(opt);
  throw InputError("study", opt.name,
                   "unknown study; known: cg, fluidized_bed, jet_mill, rheometer, validation",
                   "run ./lbdem study --list");
}

}  // namespace lbdem::studies

#pragma once
// The general, config-driven DEM scenario: a box whose faces are walls, periodic or open; gravity;
// materials; a contact law; particles from explicit lists and random fills; optional plane,
// cylinder and STL walls with motion; an optional inflow (mass rate) and outlet. Quick experiments,
// the physics tests and the benchmarks are all set up through it.
//
// With a [fluid] table the box also holds a gas (lbm::LbmSolver, fluid_config.hpp), advanced
// alongside the particles but not yet coupled to them: an integer number of gas steps per DEM step,
// or of DEM steps per gas step (SubCycle), the gas stepping first in each cycle (DESIGN §2.1). A
// box with [fluid] and no particles, fills or [[materials]] is a pure gas run: the DEM then only
// keeps the clock, one DEM step per gas step, and takes no [dem] table.
#include <memory>
#include <random>
#include <string>

#include "core/config.hpp"
#include "dem/dem_solver.hpp"
#include "dem/insertion.hpp"
#include "lbm/lbm_solver.hpp"
#include "scenarios/common/cg_config.hpp"
#include "scenarios/common/dem_config.hpp"
#include "scenarios/common/dem_driver.hpp"
#include "scenarios/common/fluid_config.hpp"
#include "scenarios/common/run_context.hpp"
#include "scenarios/common/scenario.hpp"

namespace lbdem::scenarios {

class BoxScenario : public Scenario {
 public:
  /// Reads and checks the whole config (throws InputError): nothing is written here.
  explicit BoxScenario(const Config& cfg);
  void banner(Log& log) const override;
  int run(const RunContext& ctx) override;
  dem::DemSolver& solver() { return *solver_; }
  /// The gas, or null without [fluid].
  lbm::LbmSolver* gas() { return gas_.get(); }
  const FluidConfig& fluid() const { return fluid_; }
  const SubCycle& sub_cycle() const { return sub_; }
  /// Advances the gas by the steps that come before DEM step s.steps() (SubCycle).
  void advance_gas(const dem::DemSolver& s);
  /// Inflow and outlet, called by the driver before every step (public for tests that step by
  /// hand).
  void before_step(dem::DemSolver& s);
  const OutputSettings& output() const override { return out_; }

 private:
  struct Inflow {
    bool on = false;
    Vec3 lo, hi, velocity;
    double mass_rate = 0, start = 0, end = 0, period = 0;
    int material = 0;
    dem::RadiusDistribution radius;
    double inserted = 0;  // [kg]
  };
  struct Outlet {
    bool on = false;
    Vec3 lo, hi;
    std::int64_t every = 100;
  };

  std::unique_ptr<dem::DemSolver> solver_;
  std::unique_ptr<lbm::LbmSolver> gas_;
  FluidConfig fluid_;
  SubCycle sub_;
  bool gas_only_ = false;
  OutputSettings out_;
  StepChoice step_;
  CoarseGrain cg_;
  Inflow inflow_;
  Outlet outlet_;
  std::mt19937_64 rng_;
  std::vector<std::string> wall_columns_;
};

}  // namespace lbdem::scenarios

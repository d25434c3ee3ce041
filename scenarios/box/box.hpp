#pragma once
// The general, config-driven DEM scenario: a box whose faces are walls, periodic or open; gravity;
// materials; a contact law; particles from explicit lists and random fills; optional plane,
// cylinder and STL walls with motion; an optional inflow (mass rate) and outlet. Quick experiments,
// the physics tests and the benchmarks are all set up through it.
//
// With a [fluid] table the box also holds a gas (lbm::LbmSolver, fluid_config.hpp), advanced
// alongside the particles by run::CoupledGas: an integer number of gas steps per DEM step, or of
// DEM steps per gas step (SubCycle), the gas stepping first in each cycle (docs/physics.md, Coupled
// time step). With [coupling] as well (coupling_config.hpp) gas and particles exchange momentum
// (coupling/coupler.hpp) once per exchange interval of whole cycles: the gas runs the interval's
// steps first, then the DEM. A box with [fluid] and no particles, fills or [[materials]] is a pure
// gas run: the gas's steps are the clock (run::RunLoop without particles) and it takes no [dem]
// table; its timeseries.csv holds time_s and the gas's columns, and it writes no particle files.
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "core/config.hpp"
#include "dem/dem_solver.hpp"
#include "dem/insertion.hpp"
#include "lbm/lbm_solver.hpp"
#include "coupling/coupler.hpp"
#include "run/coupled_gas.hpp"
#include "scenarios/common/cg_config.hpp"
#include "scenarios/common/coupling_config.hpp"
#include "scenarios/common/dem_config.hpp"
#include "run/run_loop.hpp"
#include "scenarios/common/fluid_config.hpp"
#include "scenarios/common/fluid_output.hpp"
#include "run/run_context.hpp"
#include "scenarios/common/scenario.hpp"

namespace lbdem::scenarios {

/// The box is also the observer of its run (run/observer.hpp): the feed and outlet before each
/// step, its walls', gas's and exchange's columns, the gas's snapshots and health; a scenario built
/// on it adds its own observer with extend().
class BoxScenario : public Scenario, public run::Observer {
 public:
  /// Reads and checks the whole config (throws InputError): nothing is written here.
  explicit BoxScenario(const Config& cfg);
  void banner(Log& log) const override;
  int run(const RunContext& ctx) override;
  dem::DemSolver& solver() { return *solver_; }
  const dem::DemSolver& solver() const { return *solver_; }
  const lbm::LbmSolver* gas() const { return gas_ ? &gas_->gas() : nullptr; }
  const coupling::Coupler* coupler() const { return gas_ ? gas_->coupler() : nullptr; }
  /// The gas, or null without [fluid].
  lbm::LbmSolver* gas() { return gas_ ? &gas_->gas() : nullptr; }
  const FluidConfig& fluid() const { return fluid_; }
  const SubCycle& sub_cycle() const { return sub_; }
  /// The exchange, or null without [coupling].
  coupling::Coupler* coupler() { return gas_ ? gas_->coupler() : nullptr; }
  /// DEM steps at which every solver stands at the same time (output and checkpoint instants).
  std::int64_t cycle() const;
  std::vector<std::string> columns() const override;
  /// A scenario built on the box (fluidized bed, jet mill) takes part in the run through its own
  /// observer, called after the box's (not owned; its columns follow the box's).
  void extend(run::Observer* o) { extension_ = o; }
  /// A DEM wall from a scenario built on the box, with its timeseries columns (before run()).
  void add_wall(dem::Wall w);
  /// Lets a scenario built on the box shape the gas after the box made it (solid cells, sources:
  /// the jet mill's chamber), then builds the exchange for the gas as shaped (its kernel leaves the
  /// solid cells out when built). Only for a box with a gas (throws std::logic_error otherwise).
  template <class Shape>
  void shape_gas(Shape&& shape) {
    if (!gas_) throw std::logic_error("BoxScenario::shape_gas: the box has no gas");
    shape(gas_->gas());
    rebuild_coupler();
  }

  // The box's part in the run (run::Observer). before_step is public for tests that step by hand.
  std::vector<std::string> row_columns() const override;
  void on_row(const run::Instant& now, std::vector<double>& row) const override;
  void before_step(const run::Instant& now) override;
  void on_checkpoint(H5Out& f) const override;
  void on_resume(const H5In& f) override;
  void on_snapshot(const std::string& dir, const std::vector<double>& times,
                   const std::vector<run::SnapshotArray>& gas_arrays) override;
  std::optional<std::string> health(const run::Instant& now) override;

  const OutputSettings& output() const override { return out_; }
  std::array<std::int64_t, 3> lattice() const override;
  /// The DEM watchdog's limits (run_loop.hpp): off for a pure gas run; the walls a scenario
  /// built on the box added count.
  DemWatch watch() const;

 private:
  /// Sets each ramped inlet to its velocity at time t [s] (before every gas step).
  void ramp_inlets(double t);
  /// Builds the exchange anew for the gas's current solid cells. No-op without [coupling].
  void rebuild_coupler();
  /// The run's warnings that are said once (a feed behind its rate, clipped gas fractions).
  void warn_once(const run::Instant& now);

  struct Inflow {
    bool on = false;
    Vec3 lo, hi, velocity;
    double mass_rate = 0, start = 0, end = 0, period = 0;
    int material = 0;
    dem::RadiusDistribution radius;
    double inserted = 0;                       // [kg]
    double behind_at = -1, behind_target = 0;  // when the feed first fell behind its rate [s, kg]
    bool behind_warned = false;
  };
  struct Outlet {
    bool on = false;
    Vec3 lo, hi;
    std::int64_t every = 100;
  };

  std::unique_ptr<dem::DemSolver> solver_;
  std::unique_ptr<run::CoupledGas> gas_;  // the gas and, coupled, the exchange; null without gas
  CouplingConfig coupling_;
  std::array<Vec3, 6> inlet_set_;  // inflow velocity last given to each ramped face [m/s]
  run::Observer* extension_ = nullptr;
  Log* log_ = nullptr;  // the run's log while run() runs (warnings said once)
  bool clip_warned_ = false;
  bool mach_warned_ = false;  // check_fluid_mach: said once per run
  FluidConfig fluid_;
  SubCycle sub_;
  bool gas_only_ = false;
  bool coupled_ = false;  // [coupling]: gas and particles exchange momentum
  OutputSettings out_;
  StepChoice step_;
  std::vector<Implausible> implausible_;  // warned about in the banner
  CoarseGrain cg_;
  Inflow inflow_;
  Outlet outlet_;
  std::mt19937_64 rng_;
  std::vector<std::string> wall_columns_;
};

}  // namespace lbdem::scenarios

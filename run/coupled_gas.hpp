#pragma once
// The gas of a run with particles, kept in step with the DEM: it owns the gas and, coupled, the
// exchange (coupling/coupler.hpp), and advances the gas by the steps that come before each DEM step
// (run/clock.hpp): the gas leads, by the DEM step it holds or, coupled, by whole exchange
// intervals, whose gas steps run first and whose exchange then drives the interval's DEM steps
// (docs/physics.md, Coupled time step). A stop (SIGINT, SIGTERM) is taken between gas steps, where
// an interval or a DEM step holds thousands of them: the caller checkpoints the gas part-way, with
// the interval's state (save_interval), and the DEM where it stands; a resume runs the rest.
#include <cstdint>
#include <functional>
#include <memory>

#include "core/h5.hpp"
#include "coupling/coupler.hpp"
#include "dem/dem_solver.hpp"
#include "lbm/lbm_solver.hpp"
#include "run/clock.hpp"

namespace lbdem::run {

class CoupledGas {
 public:
  /// `gas_dt` [s]; `before_gas_step(t)` is called before every gas step with the time [s] the step
  /// starts at (ramped inlets take their velocity there).
  CoupledGas(std::unique_ptr<lbm::LbmSolver> gas, SubCycle sub, double gas_dt,
             std::function<void(double)> before_gas_step);
  /// Couples the gas to the particles through `c`, exchanging once per `interval` (replaces an
  /// exchange built before, e.g. for a gas that was shaped after it).
  void couple(std::unique_ptr<coupling::Coupler> c, ExchangeInterval interval);

  lbm::LbmSolver& gas() { return *gas_; }
  const lbm::LbmSolver& gas() const { return *gas_; }
  /// The exchange, or null for a gas that only shares the clock.
  coupling::Coupler* coupler() { return coupler_.get(); }
  const coupling::Coupler* coupler() const { return coupler_.get(); }
  const SubCycle& sub_cycle() const { return sub_; }
  const ExchangeInterval& interval() const { return interval_; }
  /// The last exchange interval's report (drag, porosity), zero before the first.
  const coupling::ExchangeReport& report() const { return report_; }
  /// DEM steps at which the gas and the DEM stand at the same time.
  std::int64_t cycle() const { return coupler_ ? interval_.dem_steps : sub_.cycle(); }

  /// Advances the gas by the steps that come before DEM step s.steps(), or, coupled, runs the
  /// exchange interval that starts there; returns early, between gas steps, when `stop` says so,
  /// leaving behind(s) true.
  void advance(dem::DemSolver& s, const std::function<bool()>& stop);
  /// In a run without particles the gas keeps the clock: one gas step (std::logic_error when
  /// coupled).
  void step_alone();
  /// The gas's own time and step length [s].
  double time() const { return double(gas_->steps()) * dt_; }
  double dt() const { return dt_; }

  /// Gas steps done when the DEM stands at step n.
  std::int64_t steps_due(std::int64_t n) const;
  /// The gas stopped short of the steps the coming DEM step needs (a stop between gas steps).
  bool behind(const dem::DemSolver& s) const;

  /// Into a checkpoint: the gas (group /fluid: populations as stored, AA state, step count, mass
  /// ledger) and the state of an exchange interval stopped part-way, if one is
  /// (/coupling_interval).
  void save(H5Out& f) const;
  /// From a checkpoint, after the DEM was loaded: the gas (std::runtime_error if the checkpoint
  /// has none or holds it in another precision), a check that its step count is the one the DEM's
  /// implies (any other means a different time step) and an interval stopped part-way.
  void load(const H5In& f, dem::DemSolver& s);
  /// From the checkpoint of a run without particles: the gas alone.
  void load_alone(const H5In& f);

 private:
  std::unique_ptr<lbm::LbmSolver> gas_;
  std::unique_ptr<coupling::Coupler> coupler_;
  SubCycle sub_;
  ExchangeInterval interval_;
  double dt_;
  std::function<void(double)> before_gas_step_;
  coupling::ExchangeReport report_;
};

}  // namespace lbdem::run

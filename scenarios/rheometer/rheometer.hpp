#pragma once
// Powder rheometer (Anton Paar powder cell; docs/studies.md): a cylindrical cup on a floor, a
// two-blade impeller (one cuboid through the axis, 48 x 2 x 10 mm by default) with an optional
// square shaft above it, both analytic cuboids or triangle meshes. The powder is placed on a
// jittered lattice around the resting impeller, settles, and the impeller is then spun up to its
// speed. Recorded: the drive torque (torque_Nm, the torque the motor applies about +z; positive for
// positive rpm), the torques the particles put on cup and floor, and the particles' angular
// momentum about the axis (their balance is a test).
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "dem/dem_solver.hpp"
#include "scenarios/common/cg_config.hpp"
#include "scenarios/common/dem_config.hpp"
#include "run/run_loop.hpp"
#include "scenarios/common/scenario.hpp"

namespace lbdem::scenarios {

struct RheometerGeometry {
  double cup_radius = 0.025;       // [m]
  double cup_height = 0.1;         // [m]
  double blade_span = 0.048;       // tip to tip [m]
  double blade_height = 0.01;      // [m]
  double blade_thickness = 0.002;  // [m]
  double blade_bottom = 0.01;      // above the floor [m]
  double shaft_width = 0.004;      // square shaft from the blade top to the cup rim; 0: none [m]
  bool mesh = true;                // impeller as triangle meshes (false: analytic cuboids)
  double gap() const { return cup_radius - 0.5 * blade_span; }  // blade tip to cup wall [m]
};

/// Also the observer of its run: the torques and the impeller's angle in timeseries.csv.
class RheometerScenario : public Scenario, public run::Observer {
 public:
  explicit RheometerScenario(const Config& cfg);
  void banner(Log& log) const override;
  int run(const RunContext& ctx) override;
  const OutputSettings& output() const override { return out_; }
  std::vector<std::string> columns() const override;
  dem::DemSolver& solver() { return *solver_; }

  /// Drive torque about +z [N m]: minus the particles' torque on blades and shaft.
  double drive_torque() const;
  /// Angular momentum of the particles about the cup axis [N m s].
  double angular_momentum() const;
  /// Torques the particles put on the cup wall and the floor about the axis [N m].
  double cup_torque() const;
  double floor_torque() const;
  std::vector<std::string> row_columns() const override;
  void on_row(const run::Instant& now, std::vector<double>& row) const override;

 private:
  std::unique_ptr<dem::DemSolver> solver_;
  RheometerGeometry geo_;
  OutputSettings out_;
  StepChoice step_;
  std::vector<Implausible> implausible_;  // warned about in the banner
  CoarseGrain cg_;
  double rpm_ = 600, start_ = 0.2, ramp_ = 0.02;
  double fill_mass_ = 0, placed_mass_ = 0, bed_top_ = 0, mean_diameter_ = 0;
  std::vector<std::size_t> impeller_walls_;
  std::size_t cup_wall_ = 0, floor_wall_ = 0;
};

}  // namespace lbdem::scenarios

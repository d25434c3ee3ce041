#pragma once
// The spiral jet mill (docs/studies.md; Scott, Borissova, Di Renzo & Ghadiri): a flat cylindrical
// chamber, grinding jets at an angle to the wall tangent (jet_mill_geometry.hpp: the
// notional-nozzle source model and its limits), a vortex finder through the top plate, an LES gas.
// Built on the box (BoxScenario): [box] is the chamber's bounding box, [fluid] the gas (collision =
// "les"), [jet_mill] the chamber and nozzles. Particles come from [inflow] (the feed) only; their
// walls are the chamber's (cylinder, top plate with the outlet's hole) and the box's floor, and
// [coupling] works as in the box. timeseries.csv adds
//   jet_mass_flow_kg_s                 the nozzles' summed mass flow, the feed's included
//                                      (exact, the sources),
//   outlet_mass_flow_kg_s              gas leaving through the vortex finder,
//   gas_tangential_speed_mid_m_s       mean u_theta over the cells at mid-radius (|r - R/2| < dx),
//   gas_radial_speed_mid_m_s           mean u_r there (negative: inwards),
//   gas_radial_mass_flow_mid_kg_s      gas crossing the cylinder of radius nearest R/2 among
//                                      the multiples of dx, outwards, during the last gas step,
//                                      counted link by link (lbm/level_flux.hpp): the mass
//                                      balance's own flux, where the ring's mean u_r also counts
//                                      populations a wall sent back into the same cell,
//   gas_max_speed_m_s                  the largest cell speed,
//   gas_angular_momentum_z_Nms         about the chamber axis (the jets' torque spins it up),
// every gas snapshot adds radial_mass_flow_kg_per_s through the cylinders at radial_mass_flow_
// radius_m (multiples of dx; outwards, in the step before the snapshot), and the banner the jets'
// Reynolds number, mass flow, momentum flux, notional source radius, and
// cells across a nozzle, a source, the chamber height and diameter.
#include "scenarios/box/box.hpp"
#include "scenarios/jet_mill/jet_mill_geometry.hpp"

namespace lbdem::scenarios {

/// Built on the box, and the observer of the mill's own columns and snapshot data sets in its run
/// (box_.extend(this)).
class JetMillScenario : public Scenario, public run::Observer {
 public:
  explicit JetMillScenario(const Config& cfg);
  JetMillScenario(const JetMillScenario&) = delete;  // the box holds `this`
  JetMillScenario& operator=(const JetMillScenario&) = delete;
  void banner(Log& log) const override {
    box_.banner(log);
    mill_banner(log);
  }
  int run(const RunContext& ctx) override { return box_.run(ctx); }
  const OutputSettings& output() const override { return box_.output(); }
  std::array<std::int64_t, 3> lattice() const override { return box_.lattice(); }
  std::vector<std::string> columns() const override { return box_.columns(); }
  BoxScenario& box() { return box_; }
  const JetMillGeometry& geometry() const { return geometry_; }
  const JetSources& sources() const { return sources_; }
  int outlet_body() const { return outlet_; }
  /// Gas leaving through the outlet in the last gas step [kg/s].
  double outlet_mass_flow() const;
  /// The nozzles' mass flow as injected [kg/s].
  double jet_mass_flow() const;
  /// Mean tangential and radial gas velocity [m/s] over the cells at radius r (|r_c - r| < dx),
  /// from the velocity field u (lattice units, compact order).
  std::array<double, 2> ring_velocity(const std::vector<Vec3>& u, double r) const;
  /// The gas's angular momentum about the chamber axis [N m s] from u and rho (lattice, compact).
  double angular_momentum(const std::vector<Vec3>& u, const std::vector<double>& rho) const;
  /// Gas crossing the cylinders about the axis at radius k dx, k = 0, 1, ..., outwards during the
  /// last gas step [kg/s] (a cell belongs inside radius k dx when its centre does).
  std::vector<double> radial_mass_flow() const;
  /// The cylinder of radial_mass_flow() nearest R / 2.
  std::size_t mid_ring() const;
  std::vector<std::string> row_columns() const override;
  void on_row(const run::Instant& now, std::vector<double>& row) const override;
  std::vector<run::SnapshotArray> snapshot_arrays() const override;

 private:
  void mill_banner(Log& log) const;
  /// The DEM's chamber: cylinder and top plate with the vortex finder's hole (the floor is the
  /// box's z_lo face); checks the box's faces and the feed region against it.
  void add_chamber_walls(const Config& cfg);
  void check_feed_in_gas(const Config& cfg) const;

  BoxScenario box_;
  JetMillGeometry geometry_;
  JetSources sources_;
  int outlet_ = 0;
  std::vector<int> ring_level_;  // floor(r / dx) of each cell centre, compact order
  int ring_levels_ = 0;
};

}  // namespace lbdem::scenarios

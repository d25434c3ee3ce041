#pragma once
// The gas-fluidized bed (docs/studies.md; Sakai's coarse-grain model for fine cohesive powders): a
// box with a gas inlet (distributor) at the bottom and a pressure outlet at the top, particles
// poured and settled, the gas started or ramped, two-way coupled (BoxScenario with [fluid] and
// [coupling]). It adds what the study compares, in timeseries.csv:
//   bed_height_m      the height above the particles' floor (box.lo, the distributor within
//                     dx/4) below which bed.height_fraction (0.95) of the particle volume lies,
//   pressure_drop_Pa  the plane-averaged gauge pressure at bed.pressure_taps[0] minus that at
//                     bed.pressure_taps[1] (heights in m; default the distributor and the outlet,
//                     where the gas's force on the face per area of the gas grid is read; a
//                     tap at or beyond a gas face reads that face), so it holds the bed's weight
//                     and the gas's tiny hydrostatic head between the taps,
//   bed_voidage       the mean gas fraction of the kernel's eps field over the cells below the bed
//                     height less two kernel widths (the smeared top surface left out),
// and a banner with the bed's weight per area (less buoyancy, the fluidized pressure drop), the
// minimum fluidization velocity (Wen & Yu 1966; Ergun at eps = 0.4), the inflow against it, the
// Bond number of originals and parcels, and parcels across the bed width and height.
#include "scenarios/box/box.hpp"

namespace lbdem::scenarios {

/// Built on the box, and the observer of the bed's own columns in its run (box_.extend(this)).
class FluidizedBedScenario : public Scenario, public run::Observer {
 public:
  explicit FluidizedBedScenario(const Config& cfg);
  FluidizedBedScenario(const FluidizedBedScenario&) = delete;  // the box holds `this`
  FluidizedBedScenario& operator=(const FluidizedBedScenario&) = delete;
  void banner(Log& log) const override;
  int run(const RunContext& ctx) override { return box_.run(ctx); }
  const OutputSettings& output() const override { return box_.output(); }
  std::array<std::int64_t, 3> lattice() const override { return box_.lattice(); }
  std::vector<std::string> columns() const override { return box_.columns(); }
  BoxScenario& box() { return box_; }
  /// The two outputs at the solvers' current state.
  double bed_height() const;
  double pressure_drop() const;
  double bed_voidage(double bed_height) const;
  std::vector<std::string> row_columns() const override;
  void on_row(const run::Instant& now, std::vector<double>& row) const override;

 private:
  void bed_banner(Log& log) const;
  double plane_pressure(double z, const std::vector<double>& p) const;

  BoxScenario box_;
  double fraction_ = 0.95;
  std::array<double, 2> taps_{};  // [m]
  double hamaker_original_ = 0, h_min_ = 0;
  double u_in_ = 0;  // full inflow speed [m/s]
};

}  // namespace lbdem::scenarios

#pragma once
// The [fluid] part of a scenario config: the gas in SI (density, dynamic viscosity, cell size,
// time step or target lattice velocity, largest expected speed and static pressure difference,
// collision operator, body force, initial velocity, faces), checked with lbm::check_stability
// (tau, lattice Mach, Dp / (rho c_s^2); docs/physics.md, Lattice units and limits) and turned into
// lbm::LbmSettings. Every value stays in SI here; lattice values only appear in the LbmSettings
// handed to the solver.
//
// Keys (all under [fluid]):
//   density [kg/m^3], viscosity (dynamic) [Pa s], dx [m] (a periodic box edge a whole number of
//   cells; any other edge L gets round(L/dx) cells centred on it, gas walls within dx/4 of the
//   particles' walls),
//   dt [s] or lattice_velocity [-] (dt = lattice_velocity dx / max_speed, lowered to keep the
//   static Dp within 1 % of rho c_s^2), max_speed [m/s], pressure_difference [Pa] (default: the
//   hydrostatic sum_a |F_a| L_a of the force density F over the wall-bounded axes),
//   collision = "trt" (magic, default 3/16) | "bgk" | "les" (smagorinsky, default 0.1),
//   wall_function (false; true: Werner-Wengle's law of the wall on every wall at rest, for LES
//   whose first cell lies outside the viscous sublayer; lbm/boundary/wall_function.hpp),
//   precision = "double" (default) | "single" (populations f - w, the kernel's per-cell fields
//   and its arithmetic in float: half the memory and the kernel's traffic; lbm/cell.hpp),
//   body_force [N/m^3], gravity (true: + physics.gravity x density), initial_velocity [m/s],
//   [fluid.faces] x_lo .. z_hi = "wall" | "free_slip" | "periodic" |
//   {kind = "wall", slip_length = b [m]} (Navier slip; 0 no slip) |
//   {kind = "moving_wall", velocity = [..]} |
//   {kind = "inlet", velocity = [..], ramp_start = t0 [s], ramp_time = T [s], ramp_from = [..]
//   [m/s]} |
//   {kind = "outlet", pressure = p [Pa, gauge]}.
// Memory: 19 populations per cell (152 B in double, 76 B in float) plus the ghost layer.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/config.hpp"
#include "core/log.hpp"
#include "lbm/lbm_solver.hpp"
#include "lbm/units.hpp"
#include "run/clock.hpp"

namespace lbdem::scenarios {

struct FluidFace {
  std::string kind = "wall";             // wall | periodic | moving_wall | inlet | outlet
  Vec3 velocity = Vec3::Zero();          // moving_wall, inlet [m/s]
  double pressure = 0;                   // outlet, gauge pressure p - p_ref [Pa]
  bool backflow = true;                  // outlet: gas may enter through it
  double ramp_start = 0, ramp_time = 0;  // inlet: leaves ramp_from at ramp_start, full after
                                         // ramp_time [s]
  Vec3 ramp_from = Vec3::Zero();         // inlet: the inflow before ramp_start [m/s]
  double slip_length = 0;                // wall at rest: Navier slip length [m]; inf: free slip
  /// The inflow velocity at time t [m/s] (velocity itself for other kinds): ramp_from until
  /// ramp_start, then linear to velocity over ramp_time (a step when ramp_time = 0).
  Vec3 velocity_at(double t) const {
    if (kind != "inlet") return velocity;
    if (t < ramp_start) return ramp_from;
    if (ramp_time <= 0 || t >= ramp_start + ramp_time) return velocity;
    return ramp_from + (velocity - ramp_from) * ((t - ramp_start) / ramp_time);
  }
  bool ramped() const { return kind == "inlet" && (ramp_start > 0 || ramp_time > 0); }
};

struct FluidConfig {
  double density = 0;              // reference gas density rho_ref [kg/m^3]
  double viscosity = 0;            // dynamic [Pa s]
  double dx = 0, dt = 0;           // [m], [s]
  double max_speed = 0;            // [m/s]
  double pressure_difference = 0;  // static Dp for the compressibility check [Pa]
  std::string collision = "trt";   // trt | bgk | les
  double magic = 0, smagorinsky = 0;
  bool wall_function = false;
  std::string precision = "double";      // double | single (lbm/lattice_fields.hpp)
  Vec3 body_force = Vec3::Zero();        // total force density on the gas, gravity included [N/m^3]
  bool weighs = false;                   // body_force includes the gas's weight rho g
  Vec3 initial_velocity = Vec3::Zero();  // [m/s]
  std::array<FluidFace, 6> faces;        // x_lo, x_hi, y_lo, y_hi, z_lo, z_hi
  Vec3 lo = Vec3::Zero();                // lower corner of the gas grid [m]
  std::array<int, 3> cells{};            // per axis
  // The particles' box [m]. On a non-periodic axis whose edge L is not a whole number of cells
  // the grid of n = round(L/dx) cells is centred on it: lo = box_lo - wall_offset.
  Vec3 box_lo = Vec3::Zero(), box_hi = Vec3::Zero();
  std::string dt_from;                       // how dt was chosen (banner)
  double reynolds = 0, reynolds_length = 0;  // max_speed L / nu and its L [m]
  lbm::StabilityReport report{};
  /// Changes ("fluid.key = value") that pass every start-up check and may cure a divergence: a
  /// shorter time step, another operator, a finer grid; empty if none does.
  std::vector<std::string> divergence_fixes;
  /// The fix a divergence message gives: those changes, or what to do when none passes.
  std::string divergence_fix() const;
  /// Reads the same input with keys under [fluid] set (values as TOML) and others dropped: "" if
  /// every start-up check passes, else the error. For messages of a running gas that offer a
  /// change: they offer exactly what passed.
  std::function<std::string(const std::vector<std::pair<std::string, std::string>>& set,
                            const std::vector<std::string>& drop)>
      try_change;

  double nu() const { return viscosity / density; }  // kinematic [m^2/s]
  lbm::LatticeUnits units() const { return {dx, dt, density}; }
  /// The lattice set-up: cells, faces, operator and body force in lattice units.
  lbm::LbmSettings lattice() const;
  /// Lattice density of the hydrostatic rest state at cell (x, y, z): 1 + F.(x - centre) / c_s^2
  /// over the wall-bounded axes, so a gas under gravity starts in balance (mean 1).
  double rest_density(int x, int y, int z) const;
  /// SI position of a cell centre [m].
  Vec3 cell_centre(int x, int y, int z) const;
  /// Upper corner of the gas grid, lo + cells dx [m].
  Vec3 hi() const;
  /// How far the gas walls along `axis` lie outside the particles' walls [m]: (n dx - L) / 2,
  /// negative where they lie inside, within dx/4 either way; exactly 0 for a whole number of
  /// cells and on periodic axes.
  double wall_offset(int axis) const;
  /// A wall face's slip fraction s for the lattice (lbm/boundary/slip_wall.hpp): the blend of
  /// bounce-back and specular reflection has the slip length 3 nu_lattice s / (1 - s) cells, so
  /// s = b / (b + 3 nu_lattice dx) for a slip length b [m] (molecular nu; with LES the eddy
  /// viscosity shortens it near strained walls); 1 for b = inf, 0 for b = 0.
  double slip_fraction(const FluidFace& face) const;
};

/// Reads and checks [fluid] (throws InputError naming the key). `box_periodic`: the DEM box's
/// periodic axes, which the gas must share; `gravity` [m/s^2] for fluid.gravity = true.
FluidConfig read_fluid(const Config& fluid, const Vec3& lo, const Vec3& hi,
                       const std::array<bool, 3>& box_periodic, const Vec3& gravity);

// The coupled clock lives in the run layer (run/clock.hpp).
using run::conform_dem_step;
using run::SubCycle;

/// Derived gas numbers for the start-up banner (docs/user-guide.md) and the stability warnings.
void fluid_banner(Log& log, const FluidConfig& f, const SubCycle& sub);

}  // namespace lbdem::scenarios

#pragma once
// The gas part of a run folder (docs/user-guide.md), in SI only: snapshots in fluid.h5 + fluid.xdmf
// (cell data of a grid covering the lattice, at the instants of the particle snapshots: xdmf.hpp),
// timeseries.csv columns, the populations in checkpoint.h5, and the divergence watchdog. Every file
// is written atomically (H5Out, write_file_atomic), so a stopped or failed run leaves only whole
// files.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/h5.hpp"
#include "lbm/lbm_solver.hpp"
#include "run/observer.hpp"
#include "scenarios/common/fluid_config.hpp"

namespace lbdem::scenarios {

/// gas_mean_speed_m_s, gas_kinetic_energy_J, gas_mass_kg, then gas_mass_flow_<face>_kg_s (into
/// the box during the last gas step) for every inlet and outlet face, then
/// gas_force_on_walls_{x,y,z}_N: the gas's force on the box faces that are walls (momentum
/// exchange, mean of the last two gas steps: the wall shear, and the pressure on walls normal to
/// the axis), the term that closes a bed's momentum balance with the pressure drop and the particle
/// forces, and gas_mass_balance_error_kg: the gas mass less its start and all the boundaries
/// gave it (round-off; lbm::LbmSolver::exchanged_mass).
std::vector<std::string> fluid_columns(const FluidConfig& c);
std::vector<double> fluid_values(const lbm::LbmSolver& s, const FluidConfig& c);

/// Writes snapshots/fluid_NNNNNN.h5 for the last entry of `times` (index times.size() - 1) and
/// rewrites fluid.h5 (time_s; /grid: origin_m the first cell's centre, lower_corner_m, spacing_m,
/// cells; external links to every snapshot) and fluid.xdmf. Datasets, row-major
/// (z, y, x[, component]): velocity_m_per_s, pressure_Pa (p - p_ref = (rho - rho_ref) c_s^2),
/// porosity (1: no particles in the gas yet), solid (uint8: 1 in solid cells, 0 in gas); then
/// `extra`, each under /name (not in the XDMF, which lists cell fields only).
void write_fluid_snapshot(const std::string& dir, const lbm::LbmSolver& s, const FluidConfig& c,
                          const std::vector<double>& times,
                          const std::vector<run::SnapshotArray>& extra = {});

/// Watchdog limits [lattice units]: rho within +-20 % of the reference, several times the 3 %
/// that check_stability allows for the static Dp (plus ~4 % dynamic pressure at the 0.3 Mach
/// limit), so a healthy run never trips it; and speed below 0.5 (Mach 0.87), where the
/// second-order equilibrium no longer models a gas. A diverging run passes both within a few
/// dozen steps of going to NaN, so the limits catch it while the last output is still sane.
inline constexpr double kHealthyDensity = 0.2, kHealthySpeed = 0.5;

/// nullopt if every cell is within the limits; else the one-line error: simulated time, DEM and
/// gas step, the cell and its SI centre, rho / rho_ref and speed in m/s, and the fix.
std::optional<std::string> check_fluid_health(const lbm::LbmSolver& s, const FluidConfig& c,
                                              double time, std::int64_t dem_step);

/// The lattice Mach number above which a warning is due: the presets keep the lattice velocity at
/// about 0.1 (Mach 0.17), where the weakly compressible model's O(Ma^2) errors are about 3 %; at
/// Mach 0.2 they pass 4 %. A run may still be sound (a jet's core in a few cells), so it goes on.
inline constexpr double kWarnMach = 0.2;

/// nullopt if every fluid cell's speed is below lattice Mach kWarnMach; else the one-line warning:
/// time, the fastest cell with its SI centre and speed, the lattice Mach, and the fix (the step
/// that would keep it at lattice velocity 0.1, and its cost in steps). A pass over the gas.
std::optional<std::string> check_fluid_mach(const lbm::LbmSolver& s, const FluidConfig& c,
                                            double time);

}  // namespace lbdem::scenarios

#pragma once
// SI <-> lattice units in one place: the user gives dx, dt and the gas density in SI;
// every conversion below carries its dimensional formula. Lattice units never leave lbm/ and
// coupling/. With c_s = dx / (sqrt(3) dt) the lattice pressure is rho c_s^2, so a pressure
// difference Dp is a density change Dp / (rho c_s^2) (docs/physics.md, Lattice units and limits):
// in a fluidized bed the bed's pressure drop, not the Mach number, limits the time step.
#include <string>
#include <vector>

namespace lbdem::lbm {

struct LatticeUnits {
  double dx;   // cell size [m]
  double dt;   // time step [s]
  double rho;  // reference gas density [kg/m^3]

  double cs_si() const;                                // dx / (sqrt 3 dt) [m/s]
  double velocity_to_lattice(double u_si) const;       // u dt / dx
  double velocity_to_si(double u_lu) const;            // u dx / dt
  double viscosity_to_lattice(double nu_si) const;     // nu dt / dx^2
  double force_density_to_lattice(double f_si) const;  // f dt^2 / (rho dx)   (f in N/m^3)
  double force_to_si(double f_lu) const;               // F rho dx^4 / dt^2
  double torque_to_si(double t_lu) const;              // T rho dx^5 / dt^2
  double pressure_to_si(double p_lu) const;            // p rho dx^2 / dt^2
  double mass_flow_to_si(double m_lu) const;           // mdot rho dx^3 / dt
  double density_change(double dp_si) const;           // Dp / (rho c_s^2), relative [-]
};

/// The largest dt that keeps a static pressure difference dp_si [Pa] within `fraction` of
/// rho c_s^2: dt = dx sqrt(fraction rho / (3 dp)).
double max_dt_for_pressure(double dp_si, double rho, double dx, double fraction);
/// dt that puts the largest speed u_max_si at lattice velocity u_lattice: dt = u_lattice dx /
/// u_max.
double dt_for_lattice_velocity(double u_max_si, double dx, double u_lattice);

/// What the stability checks need, in SI, and the config keys to name in errors.
struct StabilityInput {
  LatticeUnits units;
  double nu_si = 0;         // kinematic viscosity [m^2/s]
  double u_max_si = 0;      // largest expected gas speed [m/s]
  double dp_static_si = 0;  // largest static pressure difference (bed weight, hydrostatic) [Pa]
  double nu_turbulent_max_si = 0;  // largest LES eddy viscosity expected (0: no LES) [m^2/s]
  // tau - 1/2 must exceed this [-]. The default suits TRT (magic 3/16), whose steady solutions do
  // not depend on tau and which the fluidized bed runs within 1e-3 of 1/2 (docs/physics.md); a BGK
  // caller passes a larger margin.
  double tau_margin = 1e-4;
  std::string key_dt = "fluid.dt", key_dx = "fluid.dx";
};

/// Derived numbers of a set-up, for the start-up banner.
struct StabilityReport {
  double tau, tau_effective_max, nu_lattice, mach, density_change;
  std::vector<std::string> warnings;
};

/// Checks tau - 1/2 (the effective one with LES), lattice Mach (error above 0.3, warning above
/// 0.2) and the static Dp / (rho c_s^2) (error above 3 %, warning above 1 %); throws InputError
/// naming the key, the value and the fix.
StabilityReport check_stability(const StabilityInput& in);

}  // namespace lbdem::lbm

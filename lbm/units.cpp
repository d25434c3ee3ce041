#include "lbm/units.hpp"

#include <cmath>

#include "core/error.hpp"
#include "lbm/d3q19.hpp"

namespace lbdem::lbm {

double LatticeUnits::cs_si() const {
  return dx / (std::sqrt(3.0) * dt);
}
double LatticeUnits::velocity_to_lattice(double u) const {
  return u * dt / dx;
}
double LatticeUnits::velocity_to_si(double u) const {
  return u * dx / dt;
}
double LatticeUnits::viscosity_to_lattice(double nu) const {
  return nu * dt / (dx * dx);
}
double LatticeUnits::force_density_to_lattice(double f) const {
  return f * dt * dt / (rho * dx);
}
double LatticeUnits::force_to_si(double f) const {
  return f * rho * dx * dx * dx * dx / (dt * dt);
}
double LatticeUnits::torque_to_si(double t) const {
  return force_to_si(t) * dx;
}
double LatticeUnits::pressure_to_si(double p) const {
  return p * rho * dx * dx / (dt * dt);
}
double LatticeUnits::mass_flow_to_si(double m) const {
  return m * rho * dx * dx * dx / dt;
}
double LatticeUnits::density_change(double dp) const {
  const double c = cs_si();
  return dp / (rho * c * c);
}

double max_dt_for_pressure(double dp, double rho, double dx, double fraction) {
  // dp / (rho c_s^2) = 3 dp dt^2 / (rho dx^2) = fraction
  return dx * std::sqrt(fraction * rho / (3.0 * dp));
}

double dt_for_lattice_velocity(double u_max, double dx, double u_lattice) {
  return u_lattice * dx / u_max;
}

StabilityReport check_stability(const StabilityInput& in) {
  const LatticeUnits& u = in.units;
  if (!(u.dx > 0)) throw InputError(in.key_dx, to_text(u.dx), "not positive", "give dx in m");
  if (!(u.dt > 0)) throw InputError(in.key_dt, to_text(u.dt), "not positive", "give dt in s");
  StabilityReport r{};
  r.nu_lattice = u.viscosity_to_lattice(in.nu_si);
  r.tau = 0.5 + r.nu_lattice / kCs2;  // nu = c_s^2 (tau - 1/2)
  r.tau_effective_max = 0.5 + u.viscosity_to_lattice(in.nu_si + in.nu_turbulent_max_si) / kCs2;
  r.mach = u.velocity_to_lattice(in.u_max_si) / std::sqrt(kCs2);
  r.density_change = u.density_change(in.dp_static_si);
  // With LES the operator is stabilised by the eddy viscosity: judge the effective tau.
  const double tau_judged = in.nu_turbulent_max_si > 0 ? r.tau_effective_max : r.tau;
  if (tau_judged - 0.5 < in.tau_margin)
    throw InputError(in.key_dt, to_text(u.dt),
                     "tau = " + to_text(tau_judged) + " is within " + to_text(in.tau_margin) +
                         " of 1/2 (nu_lattice = " + to_text(r.nu_lattice) + ")",
                     "raise dt or lower dx (tau - 1/2 = 3 nu dt / dx^2), or use the LES operator");
  if (r.mach > 0.3)
    throw InputError(
        in.key_dt, to_text(u.dt),
        "lattice Mach " + to_text(r.mach) + " above 0.3 at " + to_text(in.u_max_si) + " m/s",
        "lower dt to at most " + to_text(dt_for_lattice_velocity(in.u_max_si, u.dx, 0.1)) +
            " s (lattice velocity 0.1)");
  if (r.mach > 0.2) r.warnings.push_back("lattice Mach " + to_text(r.mach) + " above 0.2");
  if (r.density_change > 0.03)
    throw InputError(in.key_dt, to_text(u.dt),
                     "the static pressure difference " + to_text(in.dp_static_si) + " Pa is " +
                         to_text(100 * r.density_change) +
                         " % of rho c_s^2 (a weakly compressible LBM needs <= 1 %)",
                     "lower dt to at most " +
                         to_text(max_dt_for_pressure(in.dp_static_si, u.rho, u.dx, 0.01)) + " s");
  if (r.density_change > 0.01 * (1 + 1e-9))  // dt chosen for exactly 1 % passes
    r.warnings.push_back("static pressure difference is " + to_text(100 * r.density_change) +
                         " % of rho c_s^2 (above 1 %)");
  return r;
}

}  // namespace lbdem::lbm

#pragma once
// A grinding nozzle fed from a gas supply: mass flow and the momentum it delivers, from the supply
// (stagnation) pressure and temperature and the pressure it discharges into, for an ideal gas
// through a convergent nozzle with isentropic flow up to the exit (Anderson, Modern Compressible
// Flow, 3rd ed., §5.4; Shapiro 1953, ch. 4).
//   subsonic (p_a / p0 above the critical ratio (2 / (gamma + 1))^(gamma / (gamma - 1)), 0.528
//   for air): the exit is at p_a,
//     mdot = A p0 sqrt(2 gamma / ((gamma - 1) R T0) [(p_a/p0)^(2/gamma) -
//     (p_a/p0)^((gamma+1)/gamma)]), U = sqrt(2 gamma / (gamma - 1) R T0 [1 -
//     (p_a/p0)^((gamma-1)/gamma)]),  J = mdot U;
//   choked: the exit is sonic, T* = 2 T0 / (gamma + 1), p* = p0 (2 / (gamma +
//   1))^(gamma/(gamma-1)),
//     mdot = A p0 sqrt(gamma / (R T0)) (2 / (gamma + 1))^((gamma + 1) / (2 (gamma - 1)))
//     (for air 0.0404 A p0 / sqrt(T0) in SI), and the under-expanded jet carries its exit pressure
//     excess as thrust: J = mdot u* + A (p* - p_a). The jet model (jet_mill_geometry.hpp) takes
//     mdot and J, i.e. the speed U = J / mdot that conserves both across the jet's shock cells
//     (Birch, Hughes & Swaffield 1987, Combust. Sci. Technol. 52, 161: the momentum-conserving
//     pseudo-source; at 5 bar it is within 3 % of the fully expanded isentropic speed).
// Limits: no discharge coefficient (an ideal nozzle: real ones pass 0.9-1), no friction, no heat
// exchange; the gas that enters the chamber is then taken at the chamber's density (the LBM gas is
// isothermal and weakly compressible).

namespace lbdem::scenarios {

struct NozzleFlow {
  double mass_flow = 0;  // mdot [kg/s]
  double speed = 0;      // U = J / mdot [m/s]
  bool choked = false;
  double momentum_flux() const { return mass_flow * speed; }  // J [N]
};

/// p0, p_a [Pa] absolute, t0 [K], area [m^2]; gamma and the specific gas constant r [J/(kg K)]
/// default to air. Requires p0 > p_a > 0, t0 > 0, area > 0 (std::invalid_argument otherwise).
NozzleFlow nozzle_flow(double p0, double t0, double p_a, double area, double gamma = 1.4,
                       double r = 287.05);

}  // namespace lbdem::scenarios

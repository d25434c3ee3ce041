#include "scenarios/jet_mill/nozzle_flow.hpp"

#include <cmath>
#include <stdexcept>

namespace lbdem::scenarios {

NozzleFlow nozzle_flow(double p0, double t0, double p_a, double area, double gamma, double r) {
  if (!(p_a > 0 && p0 > p_a && t0 > 0 && area > 0 && gamma > 1 && r > 0))
    throw std::invalid_argument("nozzle_flow: needs p0 > p_a > 0, t0 > 0, area > 0, gamma > 1");
  const double gm1 = gamma - 1, gp1 = gamma + 1;
  const double critical = std::pow(2 / gp1, gamma / gm1);  // p*/p0
  NozzleFlow f;
  const double ratio = p_a / p0;
  if (ratio > critical) {
    f.mass_flow = area * p0 *
                  std::sqrt(2 * gamma / (gm1 * r * t0) *
                            (std::pow(ratio, 2 / gamma) - std::pow(ratio, gp1 / gamma)));
    f.speed = std::sqrt(2 * gamma / gm1 * r * t0 * (1 - std::pow(ratio, gm1 / gamma)));
    return f;
  }
  f.choked = true;
  f.mass_flow = area * p0 * std::sqrt(gamma / (r * t0)) * std::pow(2 / gp1, gp1 / (2 * gm1));
  const double u_star = std::sqrt(gamma * r * t0 * 2 / gp1);
  const double thrust = f.mass_flow * u_star + area * (critical * p0 - p_a);
  f.speed = thrust / f.mass_flow;
  return f;
}

}  // namespace lbdem::scenarios

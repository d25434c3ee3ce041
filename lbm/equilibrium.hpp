#pragma once
// Second-order equilibrium (Qian, d'Humieres & Lallemand 1992):
//   f_q^eq = w_q rho [1 + (c_q.u)/c_s^2 + (c_q.u)^2/(2 c_s^4) - u^2/(2 c_s^2)],  c_s^2 = 1/3.
#include "lbm/cell.hpp"
#include "lbm/d3q19.hpp"

namespace lbdem::lbm {

/// f_q^eq for any q (set-up and tests; the kernel uses the compile-time form in the operators).
/// inv_eps: 1/eps of the porous form (forcing/porous.hpp) on the terms of second order in u.
inline double equilibrium(int q, double rho, double ux, double uy, double uz,
                          double inv_eps = 1.0) {
  const double cu = kCx[q] * ux + kCy[q] * uy + kCz[q] * uz;
  const double usq = ux * ux + uy * uy + uz * uz;
  return kW[q] * rho * (1.0 + 3.0 * cu + inv_eps * (4.5 * cu * cu - 1.5 * usq));
}

}  // namespace lbdem::lbm

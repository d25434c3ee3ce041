#pragma once
// Damping from the coefficient of restitution.
#include <cmath>

#include "core/types.hpp"

namespace lbdem::dem {

/// beta(e) = ln e / sqrt(ln^2 e + pi^2) (Tsuji et al. 1992; Antypov & Elliott 2011). For the linear
/// spring-dashpot gamma = 2 |beta| sqrt(m* k) gives e = exp(-pi zeta/sqrt(1 - zeta^2)) with zeta =
/// |beta| exactly when the force may turn attractive before the overlap returns to zero.
inline double restitution_beta(double e) {
  if (e <= 0) return -1.0;  // critically damped limit
  const double l = std::log(e);
  return l / std::sqrt(l * l + kPi * kPi);
}

}  // namespace lbdem::dem

#include "dem/material.hpp"

#include <cmath>

namespace lbdem::dem {

MaterialPair mix(const Material& a, const Material& b) {
  MaterialPair p{};
  p.e_star = 1.0 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                    (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  p.g_star =
      1.0 / ((2 - a.poisson_ratio) / a.shear_modulus() + (2 - b.poisson_ratio) / b.shear_modulus());
  p.stiffness = 2 * a.stiffness * b.stiffness / (a.stiffness + b.stiffness);
  p.restitution = 0.5 * (a.restitution + b.restitution);
  p.friction = 0.5 * (a.friction + b.friction);
  p.rolling_friction = 0.5 * (a.rolling_friction + b.rolling_friction);
  p.hamaker = std::sqrt(a.hamaker * b.hamaker);
  return p;
}

}  // namespace lbdem::dem

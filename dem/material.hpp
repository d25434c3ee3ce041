#pragma once
// Materials in SI and the pair mixing rules (E*, G*, R*, m*) used by every contact law.
#include <string>
#include <vector>

namespace lbdem::dem {

struct Material {
  std::string name;
  double density = 2500;          // [kg/m^3]
  double youngs_modulus = 5e6;    // E [Pa] (Hertz-Mindlin)
  double poisson_ratio = 0.3;     // nu [-]
  double stiffness = 1000;        // k_n [N/m] (linear spring-dashpot)
  double restitution = 0.5;       // e [-]
  double friction = 0.5;          // sliding friction mu [-]
  double rolling_friction = 0.0;  // mu_r [-]
  double hamaker = 0.0;           // Hamaker constant A [J] (van der Waals cohesion)

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

/// Pair properties. Elastic constants follow contact mechanics (Johnson 1985, eq. 4.22 for E*;
/// Mindlin 1949 for G*); restitution, friction and rolling friction are the arithmetic mean of the
/// two materials (equal materials keep their own values); a wall is a material like any other.
struct MaterialPair {
  double e_star;            // 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 [Pa]
  double g_star;            // 1/G* = (2-nu1)/G1 + (2-nu2)/G2 [Pa]
  double stiffness;         // harmonic mean 2 k1 k2/(k1+k2) [N/m]: equal materials keep k
  double restitution;       // [-]
  double friction;          // [-]
  double rolling_friction;  // [-]
  double hamaker;           // geometric mean sqrt(A1 A2) (Israelachvili 2011, eq. 13.7) [J]
};

MaterialPair mix(const Material& a, const Material& b);

/// Effective radius R* = R1 R2/(R1+R2); a wall has R = infinity (pass r2 <= 0).
inline double effective(double a, double b) {
  return b <= 0 ? a : a * b / (a + b);
}

}  // namespace lbdem::dem

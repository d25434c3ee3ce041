#pragma once
// Shared inputs of the coarse-graining tests: the rheometer seed's HDPE contact set
// (docs/studies.md: d = 1.07 mm, rho = 950 kg/m^3, k = 1000 N/m, e = 0.8, mu = 0.55, mu_r = 0.3)
// and the Hertz modulus the DEM tests use (5 MPa; the seed gives none).
#include <omp.h>

#include "coarse_grain/scale.hpp"
#include "helpers/dem_setup.hpp"

namespace lbdem::test {

inline constexpr double kSeedRadius = 0.535e-3;  // [m]

inline dem::Material hdpe(double e = 0.8, double mu = 0.55, double mu_r = 0.3) {
  dem::Material m;
  m.name = "hdpe";
  m.density = 950;
  m.youngs_modulus = 5e6;
  m.poisson_ratio = 0.3;
  m.stiffness = 1000;
  m.restitution = e;
  m.friction = mu;
  m.rolling_friction = mu_r;
  return m;
}

inline cg::CgSettings cg_settings(cg::ScalingRule rule, double l,
                                  cg::CohesionRule c = cg::CohesionRule::bond_number) {
  cg::CgSettings s;
  s.rule = rule;
  s.cohesion = c;
  s.size_factor = l;
  return s;
}

/// One OpenMP thread for the scope, restored after. These runs hold 1 to 8 particles: threads only
/// add a barrier per step, and spinning barriers on cores shared with other jobs turned a 0.2 s
/// test into a minute when run outside ctest (which already sets OMP_NUM_THREADS=1).
class OneThread {
 public:
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(saved_); }
  OneThread(const OneThread&) = delete;
  OneThread& operator=(const OneThread&) = delete;

 private:
  int saved_ = omp_get_max_threads();
};

/// Normal law the rule is written for ("linear" or "hertz_mindlin").
inline std::string law_of(cg::ScalingRule r) {
  return std::string(cg::info(r).normal_law);
}

}  // namespace lbdem::test

#pragma once
// Small builders for the DEM tests: a solver with one material, no gravity unless asked, a big
// non-periodic 20 mm domain, and helpers for one- and two-particle experiments.
#include <cmath>

#include "dem/dem_solver.hpp"

namespace lbdem::test {

inline dem::Material glass(double e = 0.5, double mu = 0.0) {
  dem::Material m;
  m.name = "glass";
  m.density = 2500;
  m.youngs_modulus = 5e6;
  m.poisson_ratio = 0.3;
  m.stiffness = 1000;
  m.restitution = e;
  m.friction = mu;
  return m;
}

inline dem::DemSettings settings(double dt, const Vec3& g = Vec3::Zero()) {
  dem::DemSettings s;
  s.dt = dt;
  s.gravity = g;
  s.skin = 1e-4;
  // Small: the cell grid spans the domain, and a few thousand cells keep rebuilds cheap.
  s.domain.lo = Vec3(-0.01, -0.01, -0.01);
  s.domain.hi = Vec3(0.01, 0.01, 0.01);
  return s;
}

/// A plane wall through `point` with the unit `normal` pointing to the particles' side.
inline dem::Wall plane_wall(const Vec3& point, const Vec3& normal, int material = 0) {
  dem::Wall w;
  w.name = "wall";
  w.material = material;
  dem::PlaneWall p;
  p.point = point;
  p.normal = normal;
  w.shape = p;
  return w;
}

inline dem::Wall floor_wall(double z = 0, int material = 0) {
  dem::Wall w = plane_wall(Vec3(0, 0, z), Vec3::UnitZ(), material);
  w.name = "floor";
  return w;
}

/// Runs until no contact remains after one began (or max_steps); returns the steps in contact.
inline long run_through_contact(dem::DemSolver& s, long max_steps = 1000000) {
  long in = 0;
  bool seen = false;
  for (long k = 0; k < max_steps; ++k) {
    s.step();
    const bool c = s.contacts_pp() + s.contacts_pw() > 0;
    if (c) seen = true, ++in;
    if (seen && !c) break;
  }
  return in;
}

}  // namespace lbdem::test

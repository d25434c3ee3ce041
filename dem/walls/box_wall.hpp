#pragma once
// Analytic cuboid wall (particles outside), e.g. an impeller blade, with prescribed rigid motion.
// The contact point is the closest point of the solid box, so faces, edges and corners each give
// one contact with the right normal, as a finely meshed box would.
#include <array>
#include <cmath>

#include "dem/walls/plane_wall.hpp"
#include "dem/walls/prescribed_motion.hpp"

namespace lbdem::dem {

struct BoxWall {
  Vec3 center = Vec3::Zero();                                                // centre at t = 0 [m]
  std::array<Vec3, 3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};  // orthonormal [-]
  Vec3 half = Vec3::Ones();  // half extents along the axes [m]
  PrescribedMotion motion;

  /// The eight corners at time t (what the neighbour-list skin check follows).
  std::array<Vec3, 8> corners(double t) const {
    std::array<Vec3, 8> c;
    for (int k = 0; k < 8; ++k) {
      Vec3 p = center;
      for (int a = 0; a < 3; ++a) p += ((k >> a) & 1 ? 1.0 : -1.0) * half[a] * axes[a];
      c[k] = motion.position(p, t);
    }
    return c;
  }
};

inline WallPoint wall_point(const BoxWall& w, const Vec3& x, double t) {
  const Eigen::Matrix3d rot = w.motion.rotation(t);
  const Vec3 c = w.motion.position(w.center, t);
  const Vec3 d = x - c;
  std::array<Vec3, 3> ax;
  Vec3 local, q;
  bool outside = false;
  for (int a = 0; a < 3; ++a) {
    ax[a] = rot * w.axes[a];
    local[a] = d.dot(ax[a]);
    q[a] = std::clamp(local[a], -w.half[a], w.half[a]);
    outside = outside || q[a] != local[a];
  }
  if (outside) {
    const Vec3 point = c + q[0] * ax[0] + q[1] * ax[1] + q[2] * ax[2];
    const Vec3 to_wall = point - x;
    const double dist = to_wall.norm();
    return {to_wall / dist, dist, point, w.motion.velocity_at(point, t)};
  }
  // Centre inside the solid (only in a blow-up): push out through the nearest face.
  int a = 0;
  double depth = w.half[0] - std::abs(local[0]);
  for (int b = 1; b < 3; ++b)
    if (w.half[b] - std::abs(local[b]) < depth) a = b, depth = w.half[b] - std::abs(local[b]);
  const double side = local[a] >= 0 ? 1.0 : -1.0;
  const Vec3 point = x + depth * side * ax[a];
  return {-side * ax[a], -depth, point, w.motion.velocity_at(point, t)};
}

}  // namespace lbdem::dem

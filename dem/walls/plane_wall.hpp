#pragma once
// Infinite plane wall, one-sided: particles live on the side the normal points to.
#include "core/types.hpp"

namespace lbdem::dem {

struct PlaneWall {
  Vec3 point = Vec3::Zero();     // a point of the plane at t = 0 [m]
  Vec3 normal = Vec3::UnitZ();   // unit normal pointing into the particle side [-]
  Vec3 velocity = Vec3::Zero();  // translation [m/s]
};

/// Where a sphere centre sees a wall: unit normal from the centre towards the wall, distance from
/// the centre to the surface, the surface point and the wall's velocity there.
struct WallPoint {
  Vec3 n;
  double dist;
  Vec3 point;
  Vec3 wall_velocity;
};

inline WallPoint wall_point(const PlaneWall& w, const Vec3& x, double t) {
  const Vec3 p = w.point + w.velocity * t;
  const double d = (x - p).dot(w.normal);
  return {-w.normal, d, x - d * w.normal, w.velocity};
}

}  // namespace lbdem::dem

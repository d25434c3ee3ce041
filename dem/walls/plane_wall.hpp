#pragma once
// Infinite plane wall, one-sided: particles live on the side the normal points to. Optionally with
// a circular hole (a plate with an outlet, e.g. a jet mill's vortex finder): under the hole the
// nearest wall point is on the hole's rim, a sharp edge, and a centre that has passed the plane
// has left through the hole and sees no wall (a one-sided plane would throw it back).
#include <cmath>
#include <limits>

#include "core/types.hpp"

namespace lbdem::dem {

struct PlaneWall {
  Vec3 point = Vec3::Zero();        // a point of the plane at t = 0 [m]
  Vec3 normal = Vec3::UnitZ();      // unit normal pointing into the particle side [-]
  Vec3 velocity = Vec3::Zero();     // translation [m/s]
  double hole_radius = 0;           // [m]; 0: no hole
  Vec3 hole_centre = Vec3::Zero();  // in the plane at t = 0 [m]
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
  const Vec3 foot = x - d * w.normal;
  if (w.hole_radius > 0) {
    const Vec3 c = w.hole_centre + w.velocity * t;
    const Vec3 in_plane = (foot - c) - (foot - c).dot(w.normal) * w.normal;
    const double s = in_plane.norm();
    if (d < 0 && s >= w.hole_radius)  // passed the plane: it left through the hole
      return {-w.normal, std::numeric_limits<double>::infinity(), foot, w.velocity};
    if (s < w.hole_radius && s > 0) {
      const Vec3 rim = c + w.hole_radius / s * in_plane;
      const Vec3 to = rim - x;
      const double dist = to.norm();
      if (dist > 0) return {to / dist, dist, rim, w.velocity};
    }
    if (s < w.hole_radius)  // on the hole's axis (or on the rim itself): no nearest rim point
      return {-w.normal, std::numeric_limits<double>::infinity(), foot, w.velocity};
  }
  return {-w.normal, d, foot, w.velocity};
}

}  // namespace lbdem::dem

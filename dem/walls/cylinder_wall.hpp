#pragma once
// Cylindrical wall (particles inside, e.g. a cup, or outside, e.g. a shaft), optionally rotating
// about its axis and bounded along it (the end caps are separate walls).
#include <cmath>
#include <limits>

#include "dem/walls/plane_wall.hpp"

namespace lbdem::dem {

struct CylinderWall {
  Vec3 origin = Vec3::Zero();                            // a point on the axis [m]
  Vec3 axis = Vec3::UnitZ();                             // unit axis [-]
  double radius = 1;                                     // [m]
  bool inside = true;                                    // particles inside the cylinder
  double omega = 0;                                      // angular velocity about the axis [rad/s]
  double lo = -std::numeric_limits<double>::infinity();  // extent along the axis from origin [m]
  double hi = std::numeric_limits<double>::infinity();
};

/// dist < 0 or NaN-free "far" result (dist = +inf) when the centre is outside the axial extent or
/// exactly on the axis.
inline WallPoint wall_point(const CylinderWall& w, const Vec3& x, double /*t*/) {
  const Vec3 d = x - w.origin;
  const double s = d.dot(w.axis);
  const Vec3 radial = d - s * w.axis;
  const double rho = radial.norm();
  if (s < w.lo || s > w.hi || rho == 0)
    return {Vec3::UnitX(), std::numeric_limits<double>::infinity(), x, Vec3::Zero()};
  const Vec3 e = radial / rho;
  const Vec3 n = w.inside ? e : Vec3(-e);
  const double dist = w.inside ? w.radius - rho : rho - w.radius;
  const Vec3 point = w.origin + s * w.axis + w.radius * e;
  return {n, dist, point, w.omega * w.axis.cross(point - w.origin)};
}

}  // namespace lbdem::dem

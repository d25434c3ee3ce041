#pragma once
// A solid annular tube about a vertical axis (a jet mill's classifier ring): radii r_in < r_out,
// from z_lo to z_hi. Analytic and two-sided: the nearest point of a solid of revolution lies in
// the centre's meridian plane, where the tube's section is the rectangle [r_in, r_out] x
// [z_lo, z_hi], so the contact is exact on the concave inner face too (a faceted mesh there puts
// a sphere against several facets at once and double-counts its force).
#include "dem/walls/plane_wall.hpp"

#include <algorithm>
#include <cmath>

namespace lbdem::dem {

struct TubeWall {
  Vec3 axis = Vec3::Zero();  // a point on the vertical axis (its x and y are used) [m]
  double r_in = 0, r_out = 0;
  double z_lo = 0, z_hi = 0;  // [m]
};

inline WallPoint wall_point(const TubeWall& w, const Vec3& x, double /*t*/) {
  const double dx = x.x() - w.axis.x(), dy = x.y() - w.axis.y();
  const double rho = std::hypot(dx, dy);
  const Vec3 e = rho > 0 ? Vec3(dx / rho, dy / rho, 0.0) : Vec3::UnitX();
  const double qr = std::clamp(rho, w.r_in, w.r_out), qz = std::clamp(x.z(), w.z_lo, w.z_hi);
  if (qr != rho || qz != x.z()) {
    const Vec3 point(w.axis.x() + qr * e.x(), w.axis.y() + qr * e.y(), qz);
    const Vec3 to_wall = point - x;
    const double dist = to_wall.norm();
    return {to_wall / dist, dist, point, Vec3::Zero()};
  }
  // Centre inside the solid (only in a blow-up): out through the nearest face.
  const double depth[4] = {rho - w.r_in, w.r_out - rho, x.z() - w.z_lo, w.z_hi - x.z()};
  const Vec3 out[4] = {-e, e, -Vec3::UnitZ(), Vec3::UnitZ()};
  int k = 0;
  for (int j = 1; j < 4; ++j)
    if (depth[j] < depth[k]) k = j;
  return {-out[k], -depth[k], x + depth[k] * out[k], Vec3::Zero()};
}

}  // namespace lbdem::dem

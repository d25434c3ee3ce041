#include "lbm/geometry/cylinder.hpp"

#include <cmath>
#include <stdexcept>

namespace lbdem::lbm {

bool Cylinder::contains(const Vec3& x) const {
  const Vec3 n = axis.normalized();
  const Vec3 d = x - axis_point;
  const double t = d.dot(n);
  // The radial part as a vector, not |d|^2 - t^2, which cancels far along the axis.
  return t >= start && t <= end && (d - t * n).squaredNorm() <= radius * radius;
}

Cylinder Cylinder::in_lattice(const LatticeFrame& frame) const {
  // Lengths along the axis scale with dx whatever the axis' length, as they are measured along n.
  return {frame.to_lattice(axis_point), axis, radius / frame.dx, start / frame.dx, end / frame.dx};
}

Index mark_cylinder(LbmSolver& solver, const LatticeFrame& frame, const Cylinder& cylinder,
                    SolidSide side, int body) {
  if (!(cylinder.radius > 0) || !std::isfinite(cylinder.radius))
    throw std::invalid_argument("cylinder radius must be positive and finite");
  if (!(cylinder.axis.norm() > 0) || !cylinder.axis.allFinite() || !cylinder.axis_point.allFinite())
    throw std::invalid_argument("cylinder axis must be finite and non-zero");
  if (!(cylinder.start < cylinder.end))
    throw std::invalid_argument("cylinder needs start < end along its axis");
  const Cylinder c = cylinder.in_lattice(frame);
  const Vec3 n = c.axis.normalized();
  const double r2 = c.radius * c.radius;
  const bool solid_inside = side == SolidSide::inside;
  Index marked = 0;
  for_each_markable_cell(solver.grid(), [&](int x, int y, int z) {
    const Vec3 d = Vec3(x, y, z) - c.axis_point;  // contains(), with n normalised once
    const double t = d.dot(n);
    const bool in = t >= c.start && t <= c.end && (d - t * n).squaredNorm() <= r2;
    if (in == solid_inside) {
      solver.set_cell(x, y, z, body);
      ++marked;
    }
  });
  return marked;
}

}  // namespace lbdem::lbm

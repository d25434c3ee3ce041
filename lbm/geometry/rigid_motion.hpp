#pragma once
// Wall velocity of a rigid body: the moving-wall term of bounce-back (bounce_back.hpp) evaluated at
// each link's half-way point. For a body of revolution spinning about its own axis (a rheometer
// bob, a cup) the voxel set does not change, so the cells stay put and only this velocity moves.
#include "core/types.hpp"
#include "lbm/boundary/bounce_back.hpp"

#include <Eigen/Geometry>

#include <stdexcept>

namespace lbdem::lbm {

/// u(x) = U + omega n x (x - x0): rotation at `omega` [rad per time step] about the axis through
/// `axis_point` along `axis` (right-hand rule, any length > 0), plus the translation U [lattice
/// units]; x, x0 in lattice coordinates.
inline WallVelocity rigid_motion(const Vec3& axis_point, const Vec3& axis, double omega,
                                 const Vec3& translation = Vec3::Zero()) {
  const double n = axis.norm();
  if (!(n > 0) || !std::isfinite(n))
    throw std::invalid_argument("rigid_motion: the rotation axis must be finite and non-zero");
  const Vec3 w = omega / n * axis;
  return [w, axis_point, translation](const Vec3& x) -> Vec3 {
    return translation + w.cross(x - axis_point);
  };
}

}  // namespace lbdem::lbm

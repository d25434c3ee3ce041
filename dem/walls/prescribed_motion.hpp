#pragma once
// Rigid motion of a wall: translation plus rotation about an axis, switched on at a start time and
// ramped up linearly (an impeller at rest while the bed settles, then spun up to its speed).
#include <Eigen/Geometry>
#include <algorithm>

#include "core/types.hpp"

namespace lbdem::dem {

struct PrescribedMotion {
  Vec3 velocity = Vec3::Zero();    // translation at full speed [m/s]
  Vec3 axis_point = Vec3::Zero();  // a point on the rotation axis at t = 0 [m]
  Vec3 axis = Vec3::UnitZ();       // unit rotation axis [-]
  double omega = 0;                // angular velocity at full speed [rad/s] (rpm * 2 pi / 60)
  double start = 0;                // the body is at rest before this time [s]
  double ramp = 0;                 // speeds grow linearly from 0 to full over this time [s]

  bool moving() const { return omega != 0 || velocity.squaredNorm() > 0; }
  /// Fraction of full speed at time t.
  double speed_factor(double t) const {
    const double tau = t - start;
    if (tau <= 0) return 0;
    return tau < ramp ? tau / ramp : 1.0;
  }
  /// Time integral of speed_factor from 0 to t: the "full-speed time" travelled so far [s].
  double travel_time(double t) const {
    const double tau = t - start;
    if (tau <= 0) return 0;
    return tau < ramp ? 0.5 * tau * tau / ramp : tau - 0.5 * ramp;
  }
  /// Position at time t of the body point that was at p0 at t = 0; evaluated from t = 0 each time,
  /// so no error accumulates over a long run.
  Vec3 position(const Vec3& p0, double t) const {
    const double s = travel_time(t);
    const Eigen::AngleAxisd rot(omega * s, axis);
    return axis_point + velocity * s + rot * (p0 - axis_point);
  }
  /// Rotation of the body from t = 0 to t.
  Eigen::Matrix3d rotation(double t) const {
    return Eigen::AngleAxisd(omega * travel_time(t), axis).toRotationMatrix();
  }
  /// Velocity at time t of the body point now at p.
  Vec3 velocity_at(const Vec3& p, double t) const {
    const double f = speed_factor(t);
    return f * (velocity + omega * axis.cross(p - (axis_point + velocity * travel_time(t))));
  }
};

}  // namespace lbdem::dem

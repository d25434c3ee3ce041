#pragma once
// Triangle-mesh wall with prescribed rigid motion (translation plus rotation about an axis).
#include <Eigen/Geometry>

#include "dem/walls/triangle_mesh.hpp"

namespace lbdem::dem {

struct PrescribedMotion {
  Vec3 velocity = Vec3::Zero();    // translation [m/s]
  Vec3 axis_point = Vec3::Zero();  // a point on the rotation axis at t = 0 [m]
  Vec3 axis = Vec3::UnitZ();       // unit rotation axis [-]
  double omega = 0;                // angular velocity [rad/s] (rpm * 2 pi / 60)

  bool moving() const { return omega != 0 || velocity.squaredNorm() > 0; }
  /// Position at time t of the body point that was at p0 at t = 0; evaluated from t = 0 each time,
  /// so no error accumulates over a long run.
  Vec3 position(const Vec3& p0, double t) const {
    const Eigen::AngleAxisd rot(omega * t, axis);
    return axis_point + velocity * t + rot * (p0 - axis_point);
  }
  Vec3 velocity_at(const Vec3& p, double t) const {
    return velocity + omega * axis.cross(p - (axis_point + velocity * t));
  }
};

struct MeshWall {
  TriangleMesh mesh;
  PrescribedMotion motion;
  std::vector<Vec3> current;  // vertices at the current time [m]

  void update(double t) {
    current.resize(mesh.vertices.size());
    for (std::size_t k = 0; k < current.size(); ++k)
      current[k] = motion.position(mesh.vertices[k], t);
  }
  MeshClosest closest(int tri, const Vec3& x) const {
    const auto& v = mesh.triangles[tri];
    return closest_point_on_triangle(x, current[v[0]], current[v[1]], current[v[2]], tri,
                                     mesh.tri_edges[tri], v);
  }
};

}  // namespace lbdem::dem

#pragma once
// Triangle-mesh wall with prescribed rigid motion (translation plus rotation about an axis).
#include "dem/walls/prescribed_motion.hpp"
#include "dem/walls/triangle_mesh.hpp"

namespace lbdem::dem {

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

#include "dem/walls/cuboid_mesh.hpp"

namespace lbdem::dem {

TriangleMesh cuboid_mesh(const Vec3& center, const std::array<Vec3, 3>& axes, const Vec3& half) {
  // Corner k has sign bit a set for +half[a] along axes[a].
  const auto corner = [&](int k) {
    Vec3 p = center;
    for (int a = 0; a < 3; ++a) p += ((k >> a) & 1 ? 1.0 : -1.0) * half[a] * axes[a];
    return p;
  };
  std::vector<std::array<Vec3, 3>> tris;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;  // (a, b, c) cyclic: e_b x e_c = e_a
    for (int side = 0; side < 2; ++side) {
      const int base = side << a;
      const Vec3 p00 = corner(base), p10 = corner(base | (1 << b)),
                 p11 = corner(base | (1 << b) | (1 << c)), p01 = corner(base | (1 << c));
      // Counter-clockwise seen from outside: (b, c) order on the + face, reversed on the - face.
      if (side) {
        tris.push_back({p00, p10, p11});
        tris.push_back({p00, p11, p01});
      } else {
        tris.push_back({p00, p11, p10});
        tris.push_back({p00, p01, p11});
      }
    }
  }
  return TriangleMesh::from_triangles(tris);
}

}  // namespace lbdem::dem

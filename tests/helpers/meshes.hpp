#pragma once
// Triangle meshes the geometry tests build their STL files from.
#include <cmath>
#include <vector>

#include "core/stl.hpp"
#include "core/types.hpp"

namespace lbdem::test {

/// Closed prism with n sides inscribed in the cylinder (axis p + t a, t in [t0, t1], unit a),
/// facets counter-clockwise seen from outside. It lies inside the circle by at most the sagitta
/// r (1 - cos(pi / n)).
inline std::vector<Triangle> prism(const Vec3& p, const Vec3& a, double r, double t0, double t1,
                                   int n) {
  const double pi = 3.14159265358979323846;
  const Vec3 e1 = a.unitOrthogonal(), e2 = a.cross(e1);
  const Vec3 c0 = p + t0 * a, c1 = p + t1 * a;
  std::vector<Triangle> out;
  for (int k = 0; k < n; ++k) {
    const double th0 = 2 * pi * k / n, th1 = 2 * pi * (k + 1) / n;
    const Vec3 u0 = r * (std::cos(th0) * e1 + std::sin(th0) * e2);
    const Vec3 u1 = r * (std::cos(th1) * e1 + std::sin(th1) * e2);
    out.push_back({c0, c0 + u1, c0 + u0});
    out.push_back({c1, c1 + u0, c1 + u1});
    out.push_back({c0 + u0, c0 + u1, c1 + u1});
    out.push_back({c0 + u0, c1 + u1, c1 + u0});
  }
  return out;
}

}  // namespace lbdem::test

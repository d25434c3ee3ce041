#include "lbm/geometry/mesh_voxelizer.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lbdem::lbm {
namespace {

// Corner (y, z) in units of 2^-12 cells. With |coordinate| < 2^17 cells, differences stay below
// 2^30 units and each product of the orientation below 2^60: exact in int64.
constexpr double kUnitsPerCell = 4096.0;
constexpr double kMaxCoordinate = 131072.0;  // 2^17 cells

struct Corner {
  double x;           // lattice coordinate, not rounded (the crossing position)
  std::int64_t y, z;  // rounded, kUnitsPerCell per cell
};

/// Sign of the orientation of (p, u, v) in the (y, z) plane, with p moved to (y + e, z + e^2):
/// (u - p) x (v - p) + (v - u) x (e, e^2) = E + (v_y - u_y) e^2 - (v_z - u_z) e. Antisymmetric in
/// (u, v), so two facets sharing an edge see the ray on opposite sides of it, as they must.
int orientation_sign(std::int64_t uy, std::int64_t uz, std::int64_t vy, std::int64_t vz) {
  const std::int64_t e = uy * vz - uz * vy;  // u, v relative to p
  if (e != 0) return e > 0 ? 1 : -1;
  if (vz != uz) return vz < uz ? 1 : -1;
  return vy > uy ? 1 : (vy < uy ? -1 : 0);  // 0 only for coincident u, v: a degenerate facet
}

}  // namespace

Index mark_mesh(LbmSolver& solver, const LatticeFrame& frame,
                const std::vector<Triangle>& triangles, SolidSide side, int body,
                const std::string& key) {
  const Grid& g = solver.grid();
  int lo[3], hi[3];  // markable range per axis (for_each_markable_cell)
  for (int a = 0; a < 3; ++a) {
    lo[a] = g.periodic(a) ? 0 : -1;
    hi[a] = g.periodic(a) ? g.extent(a) - 1 : g.extent(a);
  }
  const int rows_y = hi[1] - lo[1] + 1, rows_z = hi[2] - lo[2] + 1;
  // Crossing positions x per row (y, z), row index (y - lo) + rows_y (z - lo).
  std::vector<std::vector<double>> crossings(std::size_t(rows_y) * std::size_t(rows_z));

  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Corner c[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = frame.to_lattice(triangles[t][std::size_t(k)]);
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() >= kMaxCoordinate)
        throw InputError(key, "",
                         "facet " + std::to_string(t) +
                             " (0-based) has a corner that is not "
                             "finite or lies beyond 2^17 cells from the lattice",
                         "check the geometry's scale and position");
      c[k] = {p.x(), std::llround(p.y() * kUnitsPerCell), std::llround(p.z() * kUnitsPerCell)};
    }
    // Rows whose ray can meet the facet: y * units in [min y, max y], likewise z.
    const auto [ymin, ymax] = std::minmax({c[0].y, c[1].y, c[2].y});
    const auto [zmin, zmax] = std::minmax({c[0].z, c[1].z, c[2].z});
    const int y0 = std::max(lo[1], int(std::ceil(double(ymin) / kUnitsPerCell)));
    const int y1 = std::min(hi[1], int(std::floor(double(ymax) / kUnitsPerCell)));
    const int z0 = std::max(lo[2], int(std::ceil(double(zmin) / kUnitsPerCell)));
    const int z1 = std::min(hi[2], int(std::floor(double(zmax) / kUnitsPerCell)));
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y) {
        const std::int64_t py = std::int64_t(y) * std::int64_t(kUnitsPerCell);
        const std::int64_t pz = std::int64_t(z) * std::int64_t(kUnitsPerCell);
        std::int64_t ry[3], rz[3];
        for (int k = 0; k < 3; ++k) ry[k] = c[k].y - py, rz[k] = c[k].z - pz;
        const int s0 = orientation_sign(ry[1], rz[1], ry[2], rz[2]);  // opposite corner 0
        const int s1 = orientation_sign(ry[2], rz[2], ry[0], rz[0]);
        const int s2 = orientation_sign(ry[0], rz[0], ry[1], rz[1]);
        if (s0 == 0 || s0 != s1 || s1 != s2) continue;
        // Barycentric weights of the ray in the facet's projection (exact in int64, then doubled:
        // the crossing position needs no exactness). A facet edge-on to the ray (zero projected
        // area) never passes the sign test above with the perturbed ray.
        const double w0 = double(ry[1] * rz[2] - rz[1] * ry[2]);
        const double w1 = double(ry[2] * rz[0] - rz[2] * ry[0]);
        const double w2 = double(ry[0] * rz[1] - rz[0] * ry[1]);
        const double area = w0 + w1 + w2;
        // Relative to corner 0, so a facet at constant x gives that x exactly.
        const double x = c[0].x + (w1 * (c[1].x - c[0].x) + w2 * (c[2].x - c[0].x)) / area;
        crossings[std::size_t(y - lo[1]) + std::size_t(rows_y) * std::size_t(z - lo[2])].push_back(
            x);
      }
  }

  const bool solid_inside = side == SolidSide::inside;
  Index marked = 0;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y) {
      std::vector<double>& xs =
          crossings[std::size_t(y - lo[1]) + std::size_t(rows_y) * std::size_t(z - lo[2])];
      if (xs.size() % 2 != 0)
        throw InputError(key, "",
                         "the surface is not closed: lattice row (y, z) = (" + std::to_string(y) +
                             ", " + std::to_string(z) + ") crosses it " +
                             std::to_string(xs.size()) + " times, an odd number",
                         "close the mesh (fill holes, e.g. repair the STL) so it bounds a volume");
      std::sort(xs.begin(), xs.end());
      std::size_t passed = 0;  // crossings at or before x
      for (int x = lo[0]; x <= hi[0]; ++x) {
        while (passed < xs.size() && xs[passed] <= double(x)) ++passed;
        if ((passed % 2 == 1) == solid_inside) {
          solver.set_cell(x, y, z, body);
          ++marked;
        }
      }
    }
  return marked;
}

Index mark_stl(LbmSolver& solver, const LatticeFrame& frame, const std::string& path, double scale,
               SolidSide side, int body, const std::string& key) {
  return mark_mesh(solver, frame, read_stl(path, scale, key), side, body, key);
}

}  // namespace lbdem::lbm

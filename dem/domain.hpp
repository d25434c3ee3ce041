#pragma once
// Simulation box and the linked-cell grid over it.
#include <algorithm>
#include <array>
#include <cmath>

#include "core/types.hpp"

namespace lbdem::dem {

struct Domain {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<bool, 3> periodic = {false, false, false};

  Vec3 length() const { return hi - lo; }
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }
  /// Minimum-image separation along periodic axes (valid while the box is > 2 cut-offs wide).
  Vec3 min_image(Vec3 d) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) {
        const double L = hi[a] - lo[a];
        d[a] -= L * std::nearbyint(d[a] / L);
      }
    return d;
  }
  /// Wraps a position into the box along periodic axes.
  Vec3 wrap(Vec3 x) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) {
        const double L = hi[a] - lo[a];
        x[a] -= L * std::floor((x[a] - lo[a]) / L);
        if (x[a] >= hi[a]) x[a] -= L;  // round-off at the upper face
      }
    return x;
  }
};

/// Cells of edge >= the interaction cut-off along each axis, tiling the box exactly (so periodic
/// wrap-around neighbours are adjacent cells). Particles outside a non-periodic box are clamped to
/// the edge cells (clamping is 1-Lipschitz in cell units, so no pair is missed).
struct CellGrid {
  Vec3 lo = Vec3::Zero();
  Vec3 inv_h = Vec3::Ones();
  std::array<int, 3> n = {1, 1, 1};

  CellGrid() = default;
  CellGrid(const Domain& d, double cell, std::size_t max_cells = std::size_t(1) << 24) : lo(d.lo) {
    const Vec3 L = d.length();
    for (;;) {
      for (int a = 0; a < 3; ++a) {
        n[a] = std::max(1, static_cast<int>(std::floor(L[a] / cell)));
        inv_h[a] = n[a] / L[a];
      }
      if (cells() <= max_cells) break;
      cell *= 1.26;  // too many cells for the memory: coarsen (still correct, only slower)
    }
  }
  int coord(double x, int a) const {
    return std::clamp(static_cast<int>(std::floor((x - lo[a]) * inv_h[a])), 0, n[a] - 1);
  }
  std::size_t cells() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  std::size_t index(int cx, int cy, int cz) const {
    return (static_cast<std::size_t>(cz) * n[1] + cy) * n[0] + cx;
  }
  std::size_t cell_of(const Vec3& x) const {
    return index(coord(x[0], 0), coord(x[1], 1), coord(x[2], 2));
  }
};

}  // namespace lbdem::dem

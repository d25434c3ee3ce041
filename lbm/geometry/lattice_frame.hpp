#pragma once
// Where the lattice sits in SI space, and which cells a geometry may turn solid.
//
// Cell (i, j, k) is the cube [origin + (i, j, k) dx, origin + (i + 1, j + 1, k + 1) dx], centred at
// origin + (i + 1/2, j + 1/2, k + 1/2) dx. The nx x ny x nz interior then covers the box
// [origin, origin + n dx] exactly, and the half-way bounce-back wall between the ghost layer (-1 or
// n) and the first interior cell lies on the box face. Lattice coordinates (cell centres at
// integers, lbm/grid.hpp) are x_lu = (x_si - origin) / dx - 1/2.
#include "core/types.hpp"
#include "lbm/grid.hpp"

namespace lbdem::lbm {

struct LatticeFrame {
  Vec3 origin = Vec3::Zero();  // SI position of the lower corner of the interior box [m]
  double dx = 1.0;             // cell size [m]

  /// The frame in which SI and lattice coordinates coincide (dx = 1, origin at -1/2): for set-ups
  /// written in lattice units.
  static LatticeFrame lattice_units() { return {Vec3::Constant(-0.5), 1.0}; }

  Vec3 to_lattice(const Vec3& x_si) const { return (x_si - origin) / dx - Vec3::Constant(0.5); }
  Vec3 to_si(const Vec3& x_lu) const { return origin + (x_lu + Vec3::Constant(0.5)) * dx; }
  Vec3 cell_centre(int x, int y, int z) const { return to_si(Vec3(x, y, z)); }
};

/// Which side of a closed surface is solid: the body itself (an impeller, a shaft) or everything
/// around it (a fluid-filled chamber such as a rheometer cup or a jet-mill housing).
enum class SolidSide { inside, outside };

/// Calls fn(x, y, z) for every cell a geometry may mark: the interior and, on axes that are not
/// periodic, the ghost layers -1 and n. A wall face's solid lies in those ghosts, and a body that
/// reaches the face must own them so that the links there carry its velocity and load; periodic
/// ghosts are never read (grid.hpp), so they are left out.
template <class Fn>
void for_each_markable_cell(const Grid& g, Fn&& fn) {
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = g.periodic(a) ? 0 : -1;
    hi[a] = g.periodic(a) ? g.extent(a) - 1 : g.extent(a);
  }
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) fn(x, y, z);
}

}  // namespace lbdem::lbm

#pragma once
// Finite circular cylinders voxelized onto the lattice: a cell is solid when its centre lies in the
// solid (lattice_frame.hpp), the usual staircase of half-way bounce-back (Ladd 1994, JFM 271, 285).
#include "core/types.hpp"
#include "lbm/geometry/lattice_frame.hpp"
#include "lbm/lbm_solver.hpp"

#include <limits>

namespace lbdem::lbm {

/// A cylinder in SI: the points x with |(x - p) - ((x - p).n) n| <= radius and start <= (x - p).n
/// <= end, where n is the unit axis. Infinite ends (the defaults) make it run through the lattice.
struct Cylinder {
  Vec3 axis_point = Vec3::Zero();                           // a point p on the axis [m]
  Vec3 axis = Vec3::UnitZ();                                // axis direction, any length > 0
  double radius = 0;                                        // [m]
  double start = -std::numeric_limits<double>::infinity();  // extent along n from p [m]
  double end = std::numeric_limits<double>::infinity();     // [m]

  /// Whether SI point x lies in the closed cylinder (its surface counts as inside).
  bool contains(const Vec3& x) const;
  /// The same cylinder with lengths in cells, about lattice coordinates.
  Cylinder in_lattice(const LatticeFrame& frame) const;
};

/// Marks as solid cells of `body` (solver.set_cell) every cell whose centre lies inside the
/// cylinder (side inside) or outside it (side outside: a closed cylindrical chamber full of fluid),
/// ghost layers of non-periodic axes included (for_each_markable_cell). Overwrites what the cells
/// held; returns how many it marked. Throws std::invalid_argument for a radius that is not positive
/// and finite, a zero or non-finite axis, or start >= end.
Index mark_cylinder(LbmSolver& solver, const LatticeFrame& frame, const Cylinder& cylinder,
                    SolidSide side, int body);

}  // namespace lbdem::lbm

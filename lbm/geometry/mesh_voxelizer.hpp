#pragma once
// Closed triangle meshes (STL) voxelized onto the lattice by ray parity: along each lattice row
// (fixed y, z) a ray in x crosses the surface an even number of times, and a cell centre is inside
// when an odd number of crossings lie at or before it.
//
// Robustness (rays through edges and vertices are the rule, not the exception: lattice rows sit at
// integer coordinates and CAD meshes at round numbers). Each corner's (y, z) is rounded to a grid
// of 2^-12 cells, so the point-in-projected-triangle tests are exact int64 orientations; a zero
// orientation is decided by simulation of simplicity (Edelsbrunner & Muecke 1990, ACM TOG 9, 66),
// moving the ray to (y + e, z + e^2) for an infinitesimal e. Every ray then meets every edge and
// vertex on one definite side, the same for all facets sharing it, so it crosses a closed surface
// an even number of times. A crossing exactly at a cell centre counts as before it: faces on
// integer coordinates bound the half-open cell range [lo, hi) on every axis. The rounding moves the
// surface by at most 2^-13 cells in y and z, which only reassigns cells whose centre lies that
// close to it.
#include "core/stl.hpp"
#include "core/types.hpp"
#include "lbm/geometry/lattice_frame.hpp"
#include "lbm/lbm_solver.hpp"

#include <string>
#include <vector>

namespace lbdem::lbm {

/// Marks as solid cells of `body` every cell whose centre lies inside the closed mesh `triangles`
/// (SI coordinates, facet orientation irrelevant), or outside it for side outside (a chamber),
/// ghost layers of non-periodic axes included (for_each_markable_cell). Overwrites what the cells
/// held; returns how many it marked. Throws InputError naming `key` when a lattice row crosses the
/// surface an odd number of times (the mesh is not closed; an open mesh whose holes no row passes
/// through goes unnoticed, and is harmless at this resolution), or when a corner is not finite or
/// lies more than 2^17 cells from the lattice origin (the exact-arithmetic range).
Index mark_mesh(LbmSolver& solver, const LatticeFrame& frame,
                const std::vector<Triangle>& triangles, SolidSide side, int body,
                const std::string& key);

/// Reads an STL file (read_stl: `scale` multiplies its coordinates into metres) and marks it
/// (mark_mesh); `key` names the file in every InputError.
Index mark_stl(LbmSolver& solver, const LatticeFrame& frame, const std::string& path, double scale,
               SolidSide side, int body, const std::string& key);

}  // namespace lbdem::lbm

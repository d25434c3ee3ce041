#pragma once
// The lattice: nx x ny x nz fluid-capable cells plus one ghost layer on every side, x fastest.
// Ghost cells hold the solid of wall faces; periodic axes wrap indices instead, so their ghosts are
// never touched (no copy pass, and a row stays contiguous for the vectorised kernel).
#include "core/types.hpp"
#include "lbm/d3q19.hpp"

#include <algorithm>
#include <array>

namespace lbdem::lbm {

class Grid {
 public:
  /// aligned_rows: start every row's cell 0 on a 64-byte boundary (8 doubles), padding the rows;
  /// streaming stores need it (bench/lbm_bench.cpp), the AA kernel does not.
  Grid(int nx, int ny, int nz, std::array<bool, 3> periodic = {true, true, true},
       bool aligned_rows = false)
      : n_{nx, ny, nz},
        periodic_(periodic),
        lead_(aligned_rows ? 8 : 1),
        sx_(aligned_rows ? 8 + (nx + 1 + 7) / 8 * 8 : nx + 2),
        sy_(ny + 2) {
    // The offsets of a cell's 19 neighbours depend only on whether it is the first, an inner or
    // the last cell along each axis (only the first and last wrap on a periodic axis): 27 kinds,
    // tabulated once, since the AA kernel asks for them on every x range of every row.
    for (int kz = 0; kz < 3; ++kz)
      for (int ky = 0; ky < 3; ++ky)
        for (int kx = 0; kx < 3; ++kx) {
          const int at[3] = {kx, ky, kz};
          int pos[3];
          for (int a = 0; a < 3; ++a)
            pos[a] = at[a] == 0 ? 0 : at[a] == 1 ? std::min(1, n_[a] - 1) : n_[a] - 1;
          const Index n = index(pos[0], pos[1], pos[2]);
          auto& off = offsets_[std::size_t(kx + 3 * (ky + 3 * kz))];
          for (int q = 0; q < kQ; ++q)
            off[std::size_t(q)] = neighbor(pos[0], pos[1], pos[2], q) - n;
        }
  }

  int nx() const { return n_[0]; }
  int ny() const { return n_[1]; }
  int nz() const { return n_[2]; }
  int extent(int axis) const { return n_[axis]; }
  bool periodic(int axis) const { return periodic_[axis]; }

  /// Storage index of cell (x, y, z); -1 and n are the ghost layers. The one place the layout
  /// lives.
  Index index(int x, int y, int z) const { return (x + lead_) + sx_ * ((y + 1) + sy_ * (z + 1)); }
  /// Inverse of index(): {x, y, z} of storage cell n.
  std::array<int, 3> coordinates(Index n) const {
    return {int(n % sx_ - lead_), int(n / sx_ % sy_) - 1, int(n / (sx_ * sy_)) - 1};
  }
  /// Cells in storage, ghosts included.
  Index storage_cells() const { return sx_ * sy_ * Index(n_[2] + 2); }
  /// Interior cells, and their compact index (no ghosts, x fastest) used by output fields.
  Index cells() const { return Index(n_[0]) * n_[1] * n_[2]; }
  Index compact_index(int x, int y, int z) const {
    return x + Index(n_[0]) * (y + Index(n_[1]) * z);
  }

  /// Coordinate of the neighbour at x + d along `axis`: wrapped on a periodic axis, else the
  /// ghost (-1 or n) when it leaves the interior.
  int shift(int axis, int x, int d) const {
    int s = x + d;
    if (periodic_[axis]) s = s < 0 ? s + n_[axis] : (s >= n_[axis] ? s - n_[axis] : s);
    return s;
  }
  /// Storage index of the neighbour x + c_q.
  Index neighbor(int x, int y, int z, int q) const {
    return index(shift(0, x, kCx[q]), shift(1, y, kCy[q]), shift(2, z, kCz[q]));
  }
  /// neighbor(x, y, z, q) - index(x, y, z) for all q.
  /// For interior cells only (a ghost coordinate would read an inner cell's offsets).
  const std::array<Index, kQ>& neighbor_offsets(int x, int y, int z) const {
    return offsets_[std::size_t(kind(0, x) + 3 * (kind(1, y) + 3 * kind(2, z)))];
  }

 private:
  std::array<int, 3> n_;
  std::array<bool, 3> periodic_;
  Index lead_;  // position of x = 0 in a row (the ghost x = -1 sits just before it)
  Index sx_, sy_;
  // 0: the first cell along the axis, 2: the last, 1: any other (an extent of 1 is kind 0, of 2
  // kinds 0 and 2, so every kind tabulated stands for the positions it is used for).
  int kind(int axis, int i) const { return i == 0 ? 0 : (i == n_[axis] - 1 ? 2 : 1); }
  std::array<std::array<Index, kQ>, 27> offsets_{};
};

/// Calls body(y, z) for every interior row, rows split statically over the OpenMP threads
/// (each row is written by exactly one thread, so results do not depend on the thread count).
template <class Body>
void for_each_row(const Grid& g, Body&& body) {
  const int ny = g.ny(), nz = g.nz();
#pragma omp parallel for collapse(2) schedule(static)
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y) body(y, z);
}

/// The x ranges [x0, x1) of a row over which the neighbour offsets are constant: on a periodic x
/// axis the first and last cells wrap, so they are ranges of their own.
template <class Body>
void for_each_x_range(const Grid& g, Body&& body) {
  const int nx = g.nx();
  if (!g.periodic(0)) {
    body(0, nx);
  } else if (nx >= 3) {
    body(0, 1);
    body(1, nx - 1);
    body(nx - 1, nx);
  } else {
    for (int x = 0; x < nx; ++x) body(x, x + 1);
  }
}

}  // namespace lbdem::lbm

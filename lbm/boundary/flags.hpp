#pragma once
// Geometry: one uint8 per storage cell (ghosts included), FluidX3D's TYPE_S idea. 0 is fluid; any
// other value k marks a solid cell of body k, whose surface is a half-way bounce-back wall moving
// with that body's velocity. Flags are read only at set-up (bounce_back.hpp lists the links), so
// the hot loop never tests them.
#include "core/types.hpp"
#include "lbm/grid.hpp"

#include <cstdint>
#include <vector>

namespace lbdem::lbm {

using CellFlag = std::uint8_t;
inline constexpr CellFlag kFluid = 0;
inline constexpr int kMaxBodies = 255;

class FlagField {
 public:
  explicit FlagField(const Grid& g) : grid_(g), flag_(std::size_t(g.storage_cells()), kFluid) {}

  const Grid& grid() const { return grid_; }
  CellFlag at(Index n) const { return flag_[std::size_t(n)]; }
  CellFlag at(int x, int y, int z) const { return at(grid_.index(x, y, z)); }
  void set(int x, int y, int z, CellFlag f) { flag_[std::size_t(grid_.index(x, y, z))] = f; }
  bool fluid(Index n) const { return at(n) == kFluid; }

 private:
  Grid grid_;
  std::vector<CellFlag> flag_;
};

}  // namespace lbdem::lbm

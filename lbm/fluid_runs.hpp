#pragma once
// The runs of fluid cells of each row, for the collision pass (stream_collide.hpp).
#include "lbm/boundary/flags.hpp"
#include "lbm/grid.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace lbdem::lbm {

/// The runs [x0, x1) of fluid cells of every row (row y + ny z), each within one x range of
/// for_each_x_range (constant neighbour offsets).
///
/// Why collide only these: a solid cell's populations are never read as fluid. What a collided
/// solid cell would write into a fluid neighbour's slot (odd step) or leave in its own slots for
/// a fluid neighbour to read (even step) is exactly a slot its link to that neighbour overwrites
/// after the step (bounce_back.hpp), so the fluid evolves bitwise the same; in the jet mill's
/// chamber the box corners outside the cylinder are a fifth of the cells.
struct FluidRuns {
  std::vector<std::uint32_t> first;  // runs of row r: run[first[r]] .. run[first[r + 1] - 1]
  std::vector<std::array<int, 2>> run;
};

inline FluidRuns fluid_runs(const Grid& g, const FlagField& flags) {
  FluidRuns r;
  r.first.push_back(0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y) {
      for_each_x_range(g, [&](int x0, int x1) {
        for (int x = x0; x < x1;) {
          if (!flags.fluid(g.index(x, y, z))) {
            ++x;
            continue;
          }
          const int b = x;
          while (x < x1 && flags.fluid(g.index(x, y, z))) ++x;
          r.run.push_back({b, x});
        }
      });
      r.first.push_back(std::uint32_t(r.run.size()));
    }
  return r;
}

}  // namespace lbdem::lbm

#pragma once
// The runs of fluid cells of each row, for the collision pass (stream_collide.hpp).
#include "lbm/boundary/flags.hpp"
#include "lbm/grid.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace lbdem::lbm {

/// The runs [x0, x1) of cells the collision visits in every row (row y + ny z), each within one x
/// range of for_each_x_range (constant neighbour offsets): the fluid cells, each run widened over
/// solid cells to a whole number of vectors where the range allows.
///
/// Why skip solid cells: a solid cell's populations are never read as fluid. What a collided
/// solid cell would write into a fluid neighbour's slot (odd step) or leave in its own slots for
/// a fluid neighbour to read (even step) is exactly a slot its link to that neighbour overwrites
/// after the step (bounce_back.hpp), so the fluid evolves bitwise the same whether solid cells
/// are collided or not; in the jet mill's chamber the box corners outside the cylinder are a
/// fifth of the cells.
///
/// Why widen: the cell loop (stream_collide.hpp) runs in vectors of `lanes` cells and finishes a
/// run's remainder one cell at a time, several times slower per cell. On the jet mill's chamber
/// (chords of 20-110 cells) the scalar remainders took 45 % of the LES kernel's time in single
/// precision (perf, cg10_p5bar). Colliding a few solid cells in whole vectors costs less, and by
/// the argument above changes no fluid value. The collided solid cells hold meaningless values:
/// nothing reads a solid cell's populations or per-cell fields as a result.
struct FluidRuns {
  std::vector<std::uint32_t> first;  // runs of row r: run[first[r]] .. run[first[r + 1] - 1]
  std::vector<std::array<int, 2>> run;
};

inline FluidRuns fluid_runs(const Grid& g, const FlagField& flags, int lanes = 1) {
  FluidRuns r;
  r.first.push_back(0);
  std::vector<std::array<int, 2>> row;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y) {
      for_each_x_range(g, [&](int x0, int x1) {
        row.clear();
        for (int x = x0; x < x1;) {
          if (!flags.fluid(g.index(x, y, z))) {
            ++x;
            continue;
          }
          const int b = x;
          while (x < x1 && flags.fluid(g.index(x, y, z))) ++x;
          row.push_back({b, x});
        }
        // Widen each run to a multiple of `lanes`, first to the right, then to the left, within
        // the range; a run that reaches the next one merges with it and is widened again.
        std::size_t out = 0;
        for (std::size_t k = 0; k < row.size(); ++k) {
          std::array<int, 2> run = row[k];
          if (out > 0 && run[0] <= r.run.back()[1]) {  // touches the previous widened run
            run[0] = r.run.back()[0];
            r.run.pop_back();
            --out;
          }
          for (;;) {
            const int want = (run[1] - run[0] + lanes - 1) / lanes * lanes;
            const int right_limit = k + 1 < row.size() ? row[k + 1][0] : x1;
            run[1] = std::min(run[0] + want, right_limit);
            if (k + 1 < row.size() && run[1] == row[k + 1][0] && run[1] - run[0] < want) {
              run[1] = row[++k][1];  // reached the next run: merge and widen again
              continue;
            }
            const int left_limit = out > 0 ? r.run.back()[1] : x0;
            run[0] = std::max(run[1] - want, left_limit);
            break;
          }
          r.run.push_back(run);
          ++out;
        }
      });
      r.first.push_back(std::uint32_t(r.run.size()));
    }
  return r;
}

}  // namespace lbdem::lbm

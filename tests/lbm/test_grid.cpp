// lbm/grid.hpp: the tabulated neighbour offsets (27 kinds of cell) against the direct
// neighbor(x, y, z, q) - index(x, y, z) for every interior cell and direction, on every combination
// of periodic and walled axes, extents 1 to 5 (1 and 2 are where the first and last cells
// coincide or touch) and both row layouts. Equivalence, exact.
#include <catch2/catch.hpp>

#include "lbm/grid.hpp"

using lbdem::lbm::Grid;
using lbdem::lbm::kQ;

TEST_CASE("Grid: tabulated neighbour offsets equal the wrapped shifts everywhere", "[lbm]") {
  long checked = 0, wrong = 0;
  for (int pattern = 0; pattern < 8; ++pattern)
    for (bool aligned : {false, true})
      for (int nx = 1; nx <= 5; ++nx)
        for (int ny = 1; ny <= 5; ++ny)
          for (int nz = 1; nz <= 5; ++nz) {
            const Grid g(nx, ny, nz, {bool(pattern & 1), bool(pattern & 2), bool(pattern & 4)},
                         aligned);
            for (int z = 0; z < nz; ++z)
              for (int y = 0; y < ny; ++y)
                for (int x = 0; x < nx; ++x) {
                  const auto& off = g.neighbor_offsets(x, y, z);
                  for (int q = 0; q < kQ; ++q, ++checked)
                    if (off[std::size_t(q)] != g.neighbor(x, y, z, q) - g.index(x, y, z)) ++wrong;
                }
          }
  INFO(wrong << " of " << checked << " offsets differ");
  CHECK(wrong == 0);
  CHECK(checked == 16L * 15 * 15 * 15 * kQ);  // 16 grids per extent triple, (1 + .. + 5)^3 cells
}

#include <cstddef>
#include <stdexcept>
#include <string>
#include <span>
#include <vector>

#include "coupling/kernel.hpp"

namespace lbdem::coupling {

void ParticleKernel::divergence(std::span<const Vec3> j, std::vector<double>& div) const {
  if (j.size() != std::size_t(grid_.cells()))
    throw std::invalid_argument("kernel: divergence of a flux field of " +
                                std::to_string(j.size()) + " cells, the grid has " +
                                std::to_string(grid_.cells()));
  const int n[3] = {grid_.nx(), grid_.ny(), grid_.nz()};
  div.assign(j.size(), 0.0);
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const auto c = std::size_t(cell(x, y, z));
        if (!gas_[c]) continue;
        const int at[3] = {x, y, z};
        double out = 0;
        for (int a = 0; a < 3; ++a)
          for (int s = 0; s < 2; ++s) {
            int q[3] = {x, y, z};
            q[a] = grid_.shift(a, at[a], s ? 1 : -1);
            if (q[a] < 0 || q[a] >= n[a]) continue;  // a wall of the box
            const auto nb = std::size_t(cell(q[0], q[1], q[2]));
            if (!gas_[nb]) continue;  // a solid cell
            const double face = 0.5 * (j[c][a] + j[nb][a]);
            out += s ? face : -face;
          }
        div[c] = out / dx_;
      }
}

}  // namespace lbdem::coupling

#include "lbm/level_flux.hpp"

#include <stdexcept>
#include <string>

namespace lbdem::lbm {

template <class T>
std::vector<double> level_flux(const PdfField<T>& pdf, AaState s, const FlagField& flags,
                               std::span<const int> level, int levels,
                               std::span<const AddedMass> added) {
  const Grid& g = pdf.grid();
  if (levels < 1 || level.size() != std::size_t(g.cells()))
    throw std::invalid_argument("level_flux: " + std::to_string(level.size()) + " levels for " +
                                std::to_string(g.cells()) + " cells");
  const auto level_of = [&](int x, int y, int z) {
    const int l = level[std::size_t(g.compact_index(x, y, z))];
    if (l < 0 || l >= levels)
      throw std::invalid_argument("level_flux: fluid cell (" + std::to_string(x) + ", " +
                                  std::to_string(y) + ", " + std::to_string(z) + ") has level " +
                                  std::to_string(l) + ", outside [0, " + std::to_string(levels) +
                                  ")");
    return l;
  };
  std::vector<double> source;  // per storage cell, only when there are any
  if (!added.empty()) {
    source.assign(std::size_t(g.storage_cells()), 0.0);
    for (const AddedMass& a : added) source[std::size_t(a.cell)] += a.mass;
  }
  std::vector<double> flux(std::size_t(levels), 0.0);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        if (!flags.fluid(g.index(x, y, z))) continue;
        const int to = level_of(x, y, z);
        const double m = source.empty() ? 0.0 : source[std::size_t(g.index(x, y, z))];
        const T* in[kQ];
        read_pointers(pdf, s, x, y, z, in);
        for (int q = 1; q < kQ; ++q) {
          // The population f_q(y) came from x - c_q (wrapped on periodic axes); links from ghosts
          // (box faces) and solids are boundary links.
          const int sx = g.shift(0, x, -kCx[q]), sy = g.shift(1, y, -kCy[q]),
                    sz = g.shift(2, z, -kCz[q]);
          if (sx < 0 || sx >= g.nx() || sy < 0 || sy >= g.ny() || sz < 0 || sz >= g.nz() ||
              !flags.fluid(g.index(sx, sy, sz)))
            continue;
          const int from = level_of(sx, sy, sz);
          if (from == to) continue;
          const double f = PopulationCodec<T>::load(*in[q], q) - kW[q] * m;
          if (from < to)
            for (int k = from + 1; k <= to; ++k) flux[std::size_t(k)] += f;
          else
            for (int k = to + 1; k <= from; ++k) flux[std::size_t(k)] -= f;
        }
      }
  return flux;
}

template std::vector<double> level_flux(const PdfField<double>&, AaState, const FlagField&,
                                        std::span<const int>, int, std::span<const AddedMass>);
template std::vector<double> level_flux(const PdfField<float>&, AaState, const FlagField&,
                                        std::span<const int>, int, std::span<const AddedMass>);

}  // namespace lbdem::lbm

#pragma once
// Macroscopic fields from the populations in either AA state: rho = sum f_q and the Guo-corrected
// velocity u = (sum c_q f_q + F/2) / rho (cell.hpp; in a porous medium the superficial velocity of
// forcing/porous.hpp), over interior cells in compact order
// (Grid::compact_index). Solid cells report rho = 0 and u = 0.
#include "core/deterministic_sum.hpp"
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/cell.hpp"
#include "lbm/pdf_field.hpp"

#include <vector>

namespace lbdem::lbm {

/// Moments of cell (x, y, z) in state s with the force policy of the step that follows.
template <class T, class Forcing>
CellMoments cell_moments_at(const PdfField<T>& pdf, AaState s, const Forcing& forcing, int x, int y,
                            int z) {
  const T* in[kQ];
  read_pointers(pdf, s, x, y, z, in);  // a single cell is always one x range
  double f[kQ];
  for (int q = 0; q < kQ; ++q) f[q] = PopulationCodec<T>::load(*in[q], q);
  CellForce force;
  return forcing.moments(f, pdf.grid().index(x, y, z), force);
}

/// Fills rho and/or u (either may be null) for every interior cell.
template <class T, class Forcing>
void moment_fields(const PdfField<T>& pdf, AaState s, const Forcing& forcing,
                   const FlagField& flags, std::vector<double>* rho, std::vector<Vec3>* u) {
  const Grid& g = pdf.grid();
  if (rho) rho->assign(std::size_t(g.cells()), 0.0);
  if (u) u->assign(std::size_t(g.cells()), Vec3::Zero());
  for_each_row(g, [&](int y, int z) {
    for_each_x_range(g, [&](int x0, int x1) {
      const T* in[kQ];
      read_pointers(pdf, s, x0, y, z, in);
      for (int i = 0; i < x1 - x0; ++i) {
        const Index n = g.index(x0 + i, y, z);
        if (!flags.fluid(n)) continue;
        double f[kQ];
        for (int q = 0; q < kQ; ++q) f[q] = PopulationCodec<T>::load(in[q][i], q);
        CellForce force;
        const CellMoments m = forcing.moments(f, n, force);
        const auto c = std::size_t(g.compact_index(x0 + i, y, z));
        if (rho) (*rho)[c] = m.rho;
        if (u) (*u)[c] = Vec3(m.ux, m.uy, m.uz);
      }
    });
  });
}

/// Total fluid mass sum rho over fluid cells, bitwise independent of the thread count.
inline double total_mass(const std::vector<double>& rho) {
  return deterministic_sum(
      rho.size(), [&](std::size_t i) { return rho[i]; }, 0.0);
}

}  // namespace lbdem::lbm

#pragma once
// The fused stream-collide step on the AA pattern (aa_pattern.hpp), generic in the collision
// operator and the forcing policy.
//
// Scheme chosen by benchmark (bench/lbm_bench.cpp --scheme aa ab nt, periodic Taylor-Green box,
// BGK, double, N = 64, 1 thread, 2-core Xeon VM with the other core busy, 2026-11-22):
//   aa (in place, this kernel) 26.7 MLUPS, ab (two lattices, ordinary stores) 19.7 MLUPS,
//   nt (two lattices, non-temporal stores) 3.8 MLUPS.
// AA moves the fewest bytes (304 B/cell, no write-allocate) and was fastest. At 8 GB/s it is still
// compute-bound, a third of the STREAM-triad roofline: the 75 % target needs a faster collide.
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/cell.hpp"
#include "lbm/collision/collision_operator.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/grid.hpp"
#include "lbm/pdf_field.hpp"

namespace lbdem::lbm {

/// Collides `count` consecutive cells of a row: cell i reads f_q at in[q][i] and writes f_q* to
/// out[q][i]; n0 is the storage index of cell 0 (for the per-cell force). The loop is vectorised
/// across cells; with the AA addresses in and out may overlap, but only within one cell, which
/// reads all 19 values before it writes any, so `omp simd` is safe.
template <CollisionOperator C, class Forcing>
inline void collide_cells(const C& coll, const Forcing& forcing, const double* const (&in)[kQ],
                          double* const (&out)[kQ], Index n0, int count) {
#pragma omp simd
  for (int i = 0; i < count; ++i) {
    double f[kQ];
    static_for<kQ>([&](auto q) { f[q] = in[q][i]; });
    const CellForce force = forcing.at(n0 + i);
    const CellMoments m = cell_moments<Forcing::kActive>(f, force);
    coll.template relax<Forcing::kActive>(f, m, force);
    static_for<kQ>([&](auto q) { out[q][i] = f[q]; });
  }
}

/// One time step over all interior cells, starting from state s; the caller then applies the
/// boundary links for state after_step(s). Rows are split statically over the threads and every
/// cell is computed by the same instructions whatever the thread count: bitwise reproducible.
template <CollisionOperator C, class Forcing>
void stream_collide(PdfField& pdf, AaState s, const C& coll, const Forcing& forcing) {
  const Grid& g = pdf.grid();
  for_each_row(g, [&](int y, int z) {
    for_each_x_range(g, [&](int x0, int x1) {
      const double* in[kQ];
      double* out[kQ];
      read_pointers(pdf, s, x0, y, z, in);
      write_pointers(pdf, s, x0, y, z, out);
      collide_cells(coll, forcing, in, out, g.index(x0, y, z), x1 - x0);
    });
  });
}

}  // namespace lbdem::lbm

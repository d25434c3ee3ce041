#pragma once
// The fused stream-collide step on the AA pattern (aa_pattern.hpp), generic in the collision
// operator and the forcing policy.
//
// Scheme chosen by benchmark: bench/lbm_bench.cpp --scheme aa ab nt, the periodic Taylor-Green
// box of bench/peers (BGK, double, 200 steps), GCC 12 -O3 -march=native, 2-core KVM Xeon
// (Sapphire Rapids class), machine otherwise idle. STREAM triad in the same run: 15.1 GB/s on 1
// thread, 28.4 GB/s on 2, a 304 B/cell roofline of 49.6 and 93.4 MLUPS. MLUPS:
//                                          N=64 1 thr   N=64 2 thr   N=128 1 thr   N=128 2 thr
//   AA pattern, in place (this kernel)        52.2        101.8         50.7          98.9
//   two lattices, pull, ordinary stores       40.5         76.3         33.7          64.4
//   two lattices, pull, each row written      30.7         60.3         35.9          69.1
//     by _mm256_stream_pd from an L1 buffer (rows padded to 64 B; unpadded rows: 7-17 MLUPS)
// Other runs agreed within 15 % (AA: 47-58, 95-115); at N = 192 (1.1 GB), 1 thread: AA 52,
// ordinary stores 34, streaming 33. AA reaches the roofline (102-109 %; the STREAM count leaves
// out the triad's own write-allocate, so 100 % is not a hard ceiling). Ordinary stores sit at
// the 2/3 write-allocate cap once the lattice leaves the cache (N = 128: 68 %). Streaming stores
// removed that traffic but not the time (72-74 %), and need padded rows. AA also halves the memory
// (one lattice) and needs no ghost exchange: periodic axes wrap indices (grid.hpp).
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/cell.hpp"
#include "lbm/collision/collision_operator.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/fluid_runs.hpp"
#include "lbm/grid.hpp"
#include "lbm/pdf_field.hpp"

namespace lbdem::lbm {

/// Cell i of collide_cells. In single precision the rest population is set last from the cell's
/// mass (cell.hpp, rest_from_mass).
template <CollisionOperator C, class Forcing, class T>
[[gnu::always_inline]] inline void collide_cell(const C& coll, const Forcing& forcing,
                                                const T* const (&in)[kQ], T* const (&out)[kQ],
                                                Index n0, int i) {
  T f[kQ];
  static_for<kQ>([&](auto q) LBDEM_INLINE { f[q] = in[q][i]; });
  // A step's pending mass sources, added as the populations are loaded (forcing/mass_source.hpp).
  if constexpr (requires { forcing.add_mass(f, n0 + i); }) forcing.add_mass(f, n0 + i);
  CellForceT<T> force;
  const CellMomentsT<T> m = forcing.moments(f, n0 + i, force);
  coll.template relax<Forcing::kActive>(f, m, force);
  if constexpr (kShifted<T>) f[0] = rest_from_mass(f, m.drho);
  static_for<kQ>([&](auto q) LBDEM_INLINE { out[q][i] = f[q]; });
}

/// Collides `count` consecutive cells of a row: cell i reads f_q at in[q][i] and writes f_q* to
/// out[q][i]; n0 is the storage index of cell 0 (for the per-cell force). The loop is vectorised
/// across cells; with the AA addresses in and out may overlap, but only within one cell, which
/// reads all 19 values before it writes any, so `omp simd` is safe. The arithmetic runs in the
/// storage type T on the slots as stored: double f_q, or float f_q - w_q (pdf_field.hpp), which
/// the operators and forcing policies take as shifted (cell.hpp): no conversion per population.
/// The whole 64-byte vectors come first; the rest of the run (up to 15 floats or 7 doubles) in
/// half-width vectors, so that at most a quarter vector is left to GCC's scalar remainder: on the
/// jet mill's chords (fluid_runs.hpp) the scalar remainders cost more than the vectors.
template <CollisionOperator C, class Forcing, class T>
inline void collide_cells(const C& coll, const Forcing& forcing, const T* const (&in)[kQ],
                          T* const (&out)[kQ], Index n0, int count) {
  constexpr int kLanes = int(64 / sizeof(T));
  const int whole = count / kLanes * kLanes;
#pragma omp simd
  for (int i = 0; i < whole; ++i) collide_cell(coll, forcing, in, out, n0, i);
#pragma omp simd simdlen(kLanes / 2)
  for (int i = whole; i < count; ++i) collide_cell(coll, forcing, in, out, n0, i);
}

/// One time step over the fluid cells (runs; all interior cells if null), starting from state s;
/// the caller then applies the boundary links for state after_step(s). Rows are split statically
/// over the threads and every cell is computed by the same instructions whatever the thread
/// count: bitwise reproducible.
template <CollisionOperator C, class Forcing, class T>
void stream_collide(PdfField<T>& pdf, AaState s, const C& coll, const Forcing& forcing,
                    const FluidRuns* runs = nullptr) {
  const Grid& g = pdf.grid();
  const auto collide_range = [&](int x0, int x1, int y, int z) {
    const T* in[kQ];
    T* out[kQ];
    read_pointers(pdf, s, x0, y, z, in);
    write_pointers(pdf, s, x0, y, z, out);
    collide_cells(coll, forcing, in, out, g.index(x0, y, z), x1 - x0);
  };
  for_each_row(g, [&](int y, int z) {
    if (!runs) return for_each_x_range(g, [&](int x0, int x1) { collide_range(x0, x1, y, z); });
    const std::size_t row = std::size_t(y) + std::size_t(g.ny()) * std::size_t(z);
    for (std::uint32_t k = runs->first[row]; k < runs->first[row + 1]; ++k)
      collide_range(runs->run[k][0], runs->run[k][1], y, z);
  });
}

}  // namespace lbdem::lbm

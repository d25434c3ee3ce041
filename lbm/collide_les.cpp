// The stream-collide pass of the regularized LES operator, in a translation unit of its own so
// that it alone gets 512-bit vectors on AVX-512 machines (lbm/CMakeLists.txt). That kernel (the
// jet mill's: LES, porous form, per-cell force, velocity sums, stored wall moments) gains from
// them, the others lose. Measured 2026-11-24 on a 2-core VM whose CPU reports 480 MiB of L3, 2
// threads, every kernel compiled 256- against 512-bit: the jet mill's stream-collide over 1.5 ms
// of cg8_p5bar 24.3 -> 21.4 s with bitwise the same results; lbdem-bench-lbm's BGK box at 64^3
// 226 -> 191 MLUPS and at 128^3 151 -> 137; its --porous TRT kernel at 64^3 145 -> 137. So only
// this pass asks for 512 bits. (On 0.1 ms of cg1_p5bar's larger lattice the division cuts and
// 512 bits together gave 1.18x on stream-collide, against 1.45x on cg8_p5bar.)
#include "lbm/solver_passes.hpp"

namespace lbdem::lbm {

template void LbmSolver::collide_pass(const RegularizedLes&);

}  // namespace lbdem::lbm

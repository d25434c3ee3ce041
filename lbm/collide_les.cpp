// The stream-collide pass of the regularized LES operator, in a translation unit of its own so
// that it alone gets 512-bit vectors on AVX-512 machines (lbm/CMakeLists.txt). That kernel (the
// jet mill's: LES, porous form, per-cell force, velocity sums, stored wall moments) is bound by its
// arithmetic: 512-bit vectors took its stream-collide from 24.3 to 21.4 s on 1.5 ms of
// cg8_p5bar (2 threads, 2026-11-24), bitwise the same results. The memory-bound kernels lost
// with them on the same machine (BGK box 64^3: 226 -> 191 MLUPS; the fluidized bed's porous TRT
// kernel 145 -> 137), so they keep GCC's default of 256 bits.
#include "lbm/solver_passes.hpp"

namespace lbdem::lbm {

template void LbmSolver::collide_pass(const RegularizedLes&);

}  // namespace lbdem::lbm

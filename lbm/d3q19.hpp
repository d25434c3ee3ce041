#pragma once
// The D3Q19 velocity set (Qian, d'Humieres & Lallemand 1992): 1 rest, 6 axis and 12 face-diagonal
// velocities with weights 1/3, 1/18 and 1/36, lattice speed of sound c_s^2 = 1/3 (dx = dt = 1).
// Opposite directions are adjacent (q odd, q + 1), so a pair loop visits each link once; the order
// of the pairs is fixed because sums over q (density, momentum) are bitwise part of the results.
#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace lbdem::lbm {

inline constexpr int kQ = 19;
inline constexpr double kCs2 = 1.0 / 3.0;  // c_s^2 [lattice units]

//                                         0  1   2  3   4  5   6  7   8  9  10 11  12 13  14
inline constexpr std::array<int, kQ> kCx = {0,  1, -1, 0, 0,  0, 0, 1, -1, 1,
                                            -1, 1, -1, 1, -1, 0, 0, 0, 0};
inline constexpr std::array<int, kQ> kCy = {0, 0, 0, 1, -1, 0, 0,  1, -1, -1,
                                            1, 0, 0, 0, 0,  1, -1, 1, -1};
inline constexpr std::array<int, kQ> kCz = {0, 0, 0,  0,  0, 1, -1, 0,  0, 0,
                                            0, 1, -1, -1, 1, 1, -1, -1, 1};

inline constexpr double kW0 = 1.0 / 3.0, kW1 = 1.0 / 18.0, kW2 = 1.0 / 36.0;
inline constexpr std::array<double, kQ> kW = {kW0, kW1, kW1, kW1, kW1, kW1, kW1, kW2, kW2, kW2,
                                              kW2, kW2, kW2, kW2, kW2, kW2, kW2, kW2, kW2};

/// Index of -c_q.
constexpr int opposite(int q) {
  return q == 0 ? 0 : (q % 2 ? q + 1 : q - 1);
}

/// Forces a lambda to be inlined: `[&](auto q) LBDEM_INLINE { ... }`. A call left in an omp simd
/// cell loop makes it run scalar. GCC 12 left calls to cell_moments and to the TRT pair body with
/// forcing, and the porous kernel ran at 11 MLUPS against 47 for BGK (bench/lbm_bench --porous,
/// 48^3, one thread of a busy machine; 42 once the velocity sums were a compile-time choice).
#define LBDEM_INLINE __attribute__((always_inline))

/// Calls body(std::integral_constant<int, q>{}) for q = 0 .. N-1, so that c_q and w_q are
/// compile-time constants in the body and products with 0 and +-1 disappear before vectorising.
template <int N, class Body>
[[gnu::always_inline]] inline void static_for(Body&& body) {
  [&]<std::size_t... Q>(std::index_sequence<Q...>) LBDEM_INLINE {
    (body(std::integral_constant<int, static_cast<int>(Q)>{}), ...);
  }
  (std::make_index_sequence<N>{});
}

/// c_q . a with the zero components left out (-0.0 is the exact additive identity, so the
/// compiler may fold it away; 0.0 * a may not be folded under IEEE rules).
template <int q, class R>
inline R dot_c(R ax, R ay, R az) {
  R s = -0.0;
  if constexpr (kCx[q] == 1) s += ax;
  if constexpr (kCx[q] == -1) s -= ax;
  if constexpr (kCy[q] == 1) s += ay;
  if constexpr (kCy[q] == -1) s -= ay;
  if constexpr (kCz[q] == 1) s += az;
  if constexpr (kCz[q] == -1) s -= az;
  return s;
}

namespace detail {
constexpr bool near(double a, double b) {
  return (a - b) * (a - b) < 1e-30;
}
constexpr bool lattice_is_consistent() {
  double w = 0, m2[3][3] = {};
  for (int q = 0; q < kQ; ++q) {
    const int c[3] = {kCx[q], kCy[q], kCz[q]};
    const int o = opposite(q);
    if (kCx[o] != -c[0] || kCy[o] != -c[1] || kCz[o] != -c[2] || kW[o] != kW[q]) return false;
    w += kW[q];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) m2[a][b] += kW[q] * c[a] * c[b];
  }
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (!near(m2[a][b], a == b ? kCs2 : 0.0)) return false;
  return near(w, 1.0);
}
}  // namespace detail
// Weights sum to 1, second moment is c_s^2 delta_ab, opposite(q) is -c_q with the same weight.
static_assert(detail::lattice_is_consistent());

}  // namespace lbdem::lbm

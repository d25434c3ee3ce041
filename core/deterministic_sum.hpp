#pragma once
// Fixed-block reductions: the block boundaries never depend on the thread count, and the block
// partials are added serially, so a sum is bitwise the same for any OpenMP thread count
// (the determinism rule of docs/architecture.md; the alternative, reduction(+:), changes the
// summation order with the threads).
#include <cstddef>
#include <vector>

namespace lbdem {

inline constexpr std::size_t kSumBlock = 4096;

/// Sum of f(i) for i in [0, n), bitwise independent of the number of threads. `zero` is explicit
/// because Eigen types are not zero-initialised by default. `block`: entries per block, fixed by
/// the caller (smaller for costly summands, so that a few thousand of them spread over the
/// threads; the sum's rounding depends on it, never on the thread count).
template <class T, class F>
T deterministic_sum(std::size_t n, F&& f, T zero, std::size_t block = kSumBlock) {
  const std::size_t nb = (n + block - 1) / block;
  if (nb <= 1) {
    T s = zero;
    for (std::size_t i = 0; i < n; ++i) s += f(i);
    return s;
  }
  std::vector<T> part(nb, zero);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    T s = zero;
    const std::size_t end = (b + 1) * block < n ? (b + 1) * block : n;
    for (std::size_t i = b * block; i < end; ++i) s += f(i);
    part[b] = s;
  }
  T s = zero;
  for (const T& p : part) s += p;
  return s;
}

}  // namespace lbdem

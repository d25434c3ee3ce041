#pragma once
// Parallel construction of row-compressed lists (neighbour pairs, wall candidates, cell lists):
// prefix sums, a two-pass fill over fixed blocks, and a stable key sort. Each gives the same
// result whatever the number of threads: the sums are of integers, every block and row is filled
// in its own slots, and a stable sort has only one result.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

namespace lbdem::dem {

/// Below this many items a pass runs on one thread: an OpenMP region costs more than the work.
inline constexpr std::size_t kMinParallel = 4096;

/// Fixed blocks of [0, n): at least kMinParallel items each, at most 64 blocks (the serial parts
/// below are O(blocks)).
inline std::size_t block_size(std::size_t n) {
  return std::max<std::size_t>(kMinParallel, (n + 63) / 64);
}

/// Inclusive prefix sum of v in place (v[0] is usually the 0 of a `first` array).
inline void prefix_sum(std::vector<std::uint32_t>& v) {
  const std::size_t n = v.size(), block = block_size(n), nb = (n + block - 1) / block;
  if (nb <= 1) {
    for (std::size_t k = 1; k < n; ++k) v[k] += v[k - 1];
    return;
  }
  std::vector<std::uint32_t> offset(nb + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t k1 = std::min(n, (b + 1) * block);
    for (std::size_t k = b * block + 1; k < k1; ++k) v[k] += v[k - 1];
    offset[b + 1] = v[k1 - 1];
  }
  for (std::size_t b = 0; b < nb; ++b) offset[b + 1] += offset[b];
#pragma omp parallel for schedule(static)
  for (std::size_t b = 1; b < nb; ++b)
    for (std::size_t k = b * block; k < std::min(n, (b + 1) * block); ++k) v[k] += offset[b];
}

/// Two passes over fixed blocks of [0, n): count(k0, k1) returns how many items the block makes,
/// then fill(k0, k1, slot) writes them from `slot` on, blocks in order. Returns the total.
template <class Count, class Fill>
std::size_t blocked_fill(std::size_t n, Count&& count, Fill&& fill) {
  const std::size_t block = block_size(n), nb = (n + block - 1) / block;
  std::vector<std::size_t> offset(nb + 1, 0);
#pragma omp parallel for schedule(static) if (nb > 1)
  for (std::size_t b = 0; b < nb; ++b)
    offset[b + 1] = count(b * block, std::min(n, (b + 1) * block));
  for (std::size_t b = 0; b < nb; ++b) offset[b + 1] += offset[b];
#pragma omp parallel for schedule(static) if (nb > 1)
  for (std::size_t b = 0; b < nb; ++b) fill(b * block, std::min(n, (b + 1) * block), offset[b]);
  return offset[nb];
}

/// Stable sort of the indices 0..n-1 by a 32-bit key: least-significant-digit radix sort over the
/// bits in which the keys differ (none for one particle, 16 for the 37,000 cells of the bench bed),
/// in at most 11-bit digits, each pass counting and scattering fixed blocks in parallel. O(n) per
/// pass, whatever the range of the keys: a cell list sorted this way costs O(particles), not
/// O(cells). The buffers are kept for the next sort.
struct KeySort {
  std::vector<std::uint64_t> a, b;  // key << 32 | index; a holds the result
  std::vector<std::uint32_t> hist;

  std::uint32_t index(std::size_t s) const { return static_cast<std::uint32_t>(a[s]); }
  std::uint32_t key(std::size_t s) const { return static_cast<std::uint32_t>(a[s] >> 32); }

  template <class Key>
  void sort(std::size_t n, Key&& key_of) {
    a.resize(n);
    std::uint32_t lo = std::numeric_limits<std::uint32_t>::max(), hi = 0;
#pragma omp parallel for schedule(static) reduction(min                 \
                                                    : lo) reduction(max \
                                                                    : hi) if (n >= kMinParallel)
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t c = key_of(k);
      a[k] = std::uint64_t(c) << 32 | k;
      lo = std::min(lo, c), hi = std::max(hi, c);
    }
    if (n == 0 || hi == lo) return;
    const int bits = std::bit_width(hi - lo), passes = (bits + 10) / 11;
    const int width = (bits + passes - 1) / passes;
    const std::size_t buckets = std::size_t(1) << width, mask = buckets - 1;
    const std::size_t block = block_size(n), nb = (n + block - 1) / block;
    b.resize(n);
    hist.resize(nb * buckets);
    for (int pass = 0; pass < passes; ++pass) {
      const int shift = pass * width;
      const auto digit = [&](std::uint64_t v) {
        return ((static_cast<std::uint32_t>(v >> 32) - lo) >> shift) & mask;
      };
#pragma omp parallel for schedule(static) if (nb > 1)
      for (std::size_t blk = 0; blk < nb; ++blk) {
        std::uint32_t* h = hist.data() + blk * buckets;
        std::fill(h, h + buckets, 0u);
        for (std::size_t k = blk * block; k < std::min(n, (blk + 1) * block); ++k) ++h[digit(a[k])];
      }
      std::uint32_t running = 0;  // digit-major, block-minor: the scatter is stable
      for (std::size_t d = 0; d < buckets; ++d)
        for (std::size_t blk = 0; blk < nb; ++blk) {
          const std::uint32_t c = hist[blk * buckets + d];
          hist[blk * buckets + d] = running;
          running += c;
        }
#pragma omp parallel for schedule(static) if (nb > 1)
      for (std::size_t blk = 0; blk < nb; ++blk) {
        std::uint32_t* h = hist.data() + blk * buckets;
        for (std::size_t k = blk * block; k < std::min(n, (blk + 1) * block); ++k)
          b[h[digit(a[k])]++] = a[k];
      }
      a.swap(b);
    }
  }
};

/// visit(row, emit) calls emit(args...) once per item of the row, identically in both passes;
/// resize(total) sizes the storage; store(slot, row, args...) writes one item.
template <class Visit, class Resize, class Store>
void build_rows(std::size_t rows, std::vector<std::uint32_t>& first, Visit&& visit, Resize&& resize,
                Store&& store) {
  first.assign(rows + 1, 0);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t r = 0; r < rows; ++r) {
    std::uint32_t n = 0;
    visit(r, [&](auto&&...) { ++n; });
    first[r + 1] = n;
  }
  prefix_sum(first);
  resize(first[rows]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t r = 0; r < rows; ++r) {
    std::uint32_t slot = first[r];
    visit(r, [&](auto&&... item) { store(slot++, r, item...); });
  }
}

}  // namespace lbdem::dem

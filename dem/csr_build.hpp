#pragma once
// Two-pass parallel construction of a row-compressed list (neighbour pairs, wall candidates):
// count each row's items, prefix-sum, size the storage, then fill each row in its own slots. Every
// row is filled in the same order whatever the number of threads, so the list is deterministic.
#include <cstdint>
#include <vector>

namespace lbdem::dem {

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
  for (std::size_t r = 0; r < rows; ++r) first[r + 1] += first[r];
  resize(first[rows]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t r = 0; r < rows; ++r) {
    std::uint32_t slot = first[r];
    visit(r, [&](auto&&... item) { store(slot++, r, item...); });
  }
}

}  // namespace lbdem::dem

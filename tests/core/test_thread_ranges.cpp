// core/thread_ranges.hpp: the threads' ranges cover [0, n) exactly once, contiguous and in thread
// order, for item counts below, at and above the thread count (the DEM passes rely on every item
// being visited once; the order is what keeps each thread's rows together).
#include <catch2/catch.hpp>

#include "core/thread_ranges.hpp"

#include <omp.h>

#include <algorithm>
#include <utility>
#include <vector>

using namespace lbdem;

TEST_CASE("for_thread_ranges: every item once, contiguous shares in thread order", "[core]") {
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2, 3, 4}) {
    omp_set_num_threads(threads);
    for (std::size_t n :
         {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(1000), std::size_t(1001)}) {
      std::vector<int> hits(n, 0);
      std::vector<std::pair<std::size_t, std::size_t>> share(std::size_t(threads), {1, 0});
      int team = 0;
      for_thread_ranges(n, [&](std::size_t b, std::size_t e) {
        const int t = omp_get_thread_num();
#pragma omp single
        team = omp_get_num_threads();
        share[std::size_t(t)] = {b, e};
        for (std::size_t i = b; i < e; ++i) ++hits[i];  // shares are disjoint: no race
      });
      INFO("threads " << threads << ", n " << n);
      for (int h : hits) CHECK(h == 1);
      // Shares follow each other in thread order and differ in size by at most one item.
      std::size_t expect = 0, lo = n, hi = 0;
      for (int t = 0; t < team; ++t) {
        CHECK(share[std::size_t(t)].first == expect);
        expect = share[std::size_t(t)].second;
        const std::size_t len = share[std::size_t(t)].second - share[std::size_t(t)].first;
        lo = std::min(lo, len), hi = std::max(hi, len);
      }
      CHECK(expect == n);
      CHECK(hi - lo <= 1);
    }
  }
  omp_set_num_threads(saved);
}

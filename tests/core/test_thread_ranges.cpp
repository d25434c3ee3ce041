// core/thread_ranges.hpp: the threads' ranges cover [0, n) exactly once, contiguous and in thread
// order, for item counts below, at and above the thread count (the DEM passes rely on every item
// being visited once; the order is what keeps each thread's rows together); split by cost, each
// share's cost is an equal part of the total to within about one item's.
#include <catch2/catch.hpp>

#include "core/thread_ranges.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
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

TEST_CASE("for_cost_ranges: every item once, in thread order, shares of about equal cost",
          "[core]") {
  const int saved = omp_get_max_threads();
  // 1000 items: the first 900 cost 1 each, the last 100 cost 9 each (1,800 in all), as a crowded
  // wall after a dilute core in sorted order.
  const std::size_t n = 1000;
  std::vector<std::uint64_t> before(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k) before[k + 1] = before[k] + (k < 900 ? 1 : 9);
  const auto cost = [&](std::size_t k) { return before[k]; };
  for (int threads : {1, 2, 3, 4}) {
    omp_set_num_threads(threads);
    std::vector<int> hits(n, 0);
    std::vector<std::pair<std::size_t, std::size_t>> share(std::size_t(threads), {1, 0});
    int team = 0;
    for_cost_ranges(n, cost, [&](std::size_t b, std::size_t e) {
      const int t = omp_get_thread_num();
#pragma omp single
      team = omp_get_num_threads();
      share[std::size_t(t)] = {b, e};
      for (std::size_t i = b; i < e; ++i) ++hits[i];
    });
    INFO("threads " << threads);
    for (int h : hits) CHECK(h == 1);
    std::size_t expect = 0;
    for (int t = 0; t < team; ++t) {
      CHECK(share[std::size_t(t)].first == expect);
      expect = share[std::size_t(t)].second;
      // Each share's cost is within one item's cost (9) of an equal part, plus 1 for the parts'
      // rounding to whole costs.
      const double part = double(before[n]) / team;
      const auto [b, e] = share[std::size_t(t)];
      CHECK(std::abs(double(before[e] - before[b]) - part) < 10);
    }
    CHECK(expect == n);
  }
  // No items, and items that cost nothing: the shares still tile [0, n).
  omp_set_num_threads(2);
  for (std::size_t m : {std::size_t(0), std::size_t(5)}) {
    std::vector<int> hits(m, 0);
    for_cost_ranges(
        m, [](std::size_t) { return std::uint64_t(0); },
        [&](std::size_t b, std::size_t e) {
          for (std::size_t i = b; i < e; ++i) ++hits[i];
        });
    for (int h : hits) CHECK(h == 1);
  }
  omp_set_num_threads(saved);
}

#pragma once
// The check every resume test makes: two run folders hold bitwise the same checkpoint data sets
// and the same time series (no gap, no duplicate row where the run stopped and went on).
#include <catch2/catch.hpp>

#include <cstring>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/h5.hpp"
#include "helpers/cli.hpp"

namespace lbdem::test {

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

/// Each named data set of `a/checkpoint.h5` is non-empty and bitwise equal to that of `b`, and
/// the two `timeseries.csv` are equal (skipped when `timeseries` is false).
inline void check_same_runs(const std::string& a, const std::string& b,
                            std::initializer_list<const char*> sets, bool timeseries = true) {
  const lbdem::H5In fa(a + "/checkpoint.h5"), fb(b + "/checkpoint.h5");
  for (const char* set : sets) {
    INFO("checkpoint data set " << set);
    const auto x = fa.doubles(set), y = fb.doubles(set);
    REQUIRE_FALSE(x.empty());  // the state really went through the checkpoint
    CHECK(same_bits(x, y));
  }
  if (timeseries) CHECK(read_text(a + "/timeseries.csv") == read_text(b + "/timeseries.csv"));
}

}  // namespace lbdem::test

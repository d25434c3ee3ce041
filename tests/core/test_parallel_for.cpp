// core/parallel_for.hpp: an exception thrown in the loop body leaves the loop as the error of the
// lowest failing index, whatever the thread count (an exception escaping an OpenMP region would
// end the process instead).
#include <catch2/catch.hpp>

#include "core/parallel_for.hpp"

#include <omp.h>

#include <stdexcept>
#include <string>
#include <vector>

using namespace lbdem;

TEST_CASE("parallel_for: the lowest failing index's error, at 1 and 2 threads", "[core]") {
  const std::size_t n = 10000;
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    std::vector<int> done(n, 0);
    std::string what;
    try {
      // Fails early and late in the second thread's half and mid-way in the first's: neither
      // the first nor the last error caught may win, only the lowest index.
      parallel_for(n, 1, [&](std::size_t i) {
        if (i == 5001 || i == 9999 || i == 4321)
          throw std::runtime_error("bad " + std::to_string(i));
        done[i] = 1;
      });
    } catch (const std::runtime_error& e) {
      what = e.what();
    }
    CHECK(what == "bad 4321");
    // Every other index ran: one failure does not stop the rest.
    std::size_t ran = 0;
    for (int d : done) ran += std::size_t(d);
    CHECK(ran == n - 3);
  }
  omp_set_num_threads(saved);
  std::vector<int> all(100, 0);
  parallel_for(all.size(), 1000, [&](std::size_t i) { all[i] = int(i); });  // serial, no throw
  CHECK(all[99] == 99);
}

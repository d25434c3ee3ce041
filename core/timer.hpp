#pragma once
#include <chrono>

#include "core/run_clock.hpp"

namespace lbdem {

/// Wall-clock stopwatch; time suspended by SIGTSTP is left out (run_clock.hpp).
class Stopwatch {
 public:
  Stopwatch() : start_(clock::now()) {}
  void reset() { start_ = clock::now(); }
  double seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

 private:
  using clock = RunClock;
  clock::time_point start_;
};

}  // namespace lbdem

#pragma once
// Progress on stderr: simulated time, % done, ETA, throughput. On a terminal one line is updated in
// place; otherwise (CI, a log file) a line is printed every few seconds.
#include <string>

#include "core/timer.hpp"

namespace lbdem {

class Progress {
 public:
  Progress(double t_end, std::string rate_unit, double interval_s = 5.0);
  /// `work_done` counts the unit of the rate (e.g. particle-steps) since start.
  void update(double t, double work_done, bool force = false);
  void finish();

 private:
  double t_end_, interval_, t_start_ = -1, last_print_ = -1e30;
  std::string unit_;
  bool tty_;
  Stopwatch clock_;
};

}  // namespace lbdem

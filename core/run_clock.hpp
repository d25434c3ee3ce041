#pragma once
// Wall time that stands still while the process is suspended. Paper-scale runs take hours on
// machines that also build and test, and the way to free the cores for a while is to suspend the
// run (Ctrl-Z, or `kill -TSTP PID`) and continue it later (`kill -CONT PID`). The steady clock
// runs on through the suspension, so a run's cost sums, phase timers and ETA would count it as
// work. With the handler installed, SIGTSTP records the time, stops the process with SIGSTOP
// (which cannot be caught), and on SIGCONT adds the suspension to a process-wide total, which
// RunClock subtracts. A bare SIGSTOP cannot be seen by the process and is still counted.
#include <chrono>
#include <cstdint>

namespace lbdem {

/// A steady clock less the time spent suspended by SIGTSTP (with install_suspend_handler()).
struct RunClock {
  using duration = std::chrono::steady_clock::duration;
  using rep = duration::rep;
  using period = duration::period;
  using time_point = std::chrono::time_point<RunClock>;
  static constexpr bool is_steady = true;
  static time_point now() noexcept;
};

/// Installs the SIGTSTP handler (idempotent; the process still stops as by default).
void install_suspend_handler();

/// Seconds spent suspended by SIGTSTP since the handler was installed.
double suspended_seconds();

}  // namespace lbdem

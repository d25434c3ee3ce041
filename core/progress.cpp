#include "core/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace lbdem {

Progress::Progress(double t_end, std::string rate_unit, double interval_s)
    : t_end_(t_end), interval_(interval_s), unit_(std::move(rate_unit)), tty_(isatty(2)) {
  if (tty_) interval_ = 0.25;
}

void Progress::update(double t, double work_done, bool force) {
  if (t_start_ < 0) t_start_ = t;
  const double now = clock_.seconds();
  if (!force && now - last_print_ < interval_) return;
  last_print_ = now;
  const double frac = t_end_ > t_start_ ? (t - t_start_) / (t_end_ - t_start_) : 1.0;
  const double eta = frac > 0 ? now * (1 - frac) / frac : 0.0;
  const double rate = now > 0 ? work_done / now : 0.0;
  std::fprintf(stderr, "%st = %.5g s  %5.1f %%  ETA %6.0f s  %.3g %s/s%s", tty_ ? "\r" : "", t,
               100.0 * (t / t_end_), eta, rate, unit_.c_str(), tty_ ? "   " : "\n");
  std::fflush(stderr);
}

void Progress::finish() {
  if (tty_) std::fprintf(stderr, "\n");
}

}  // namespace lbdem

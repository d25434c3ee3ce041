#include "core/run_clock.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <ctime>

namespace lbdem {

namespace {

// The suspension state, read by RunClock::now() on any thread and written by the handler, which
// may run on an OpenMP worker. A sequence lock keeps the pair consistent: the writer makes the
// count odd, writes, makes it even; a reader retries until it saw one even count on both sides.
// `since` is set while a suspension is under way, so that no thread reads the uncorrected clock
// between SIGCONT and the update of the total (the clock would step back then).
std::atomic<std::uint64_t> g_seq{0};
std::atomic<std::int64_t> g_suspended_ns{0};   // total of the finished suspensions
std::atomic<std::int64_t> g_since_ns{0};       // start of the one under way, 0 if none
std::atomic_flag g_writer = ATOMIC_FLAG_INIT;  // two handlers on two threads take turns
static_assert(std::atomic<std::int64_t>::is_always_lock_free, "used from a signal handler");
static_assert(std::atomic<std::uint64_t>::is_always_lock_free, "used from a signal handler");

// clock_gettime is async-signal-safe (POSIX.1-2008 §2.4.3), so the handler and RunClock::now()
// read the same clock, CLOCK_MONOTONIC (libstdc++'s steady_clock on Linux).
std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::int64_t(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

template <class F>
void write_state(F&& f) {
  g_seq.fetch_add(1, std::memory_order_acq_rel);
  f();
  g_seq.fetch_add(1, std::memory_order_acq_rel);
}

// A SIGCONT that arrives between the handler's entry and its raise(SIGSTOP) (microseconds) finds
// the process running and is lost: the process then stays stopped until the next SIGCONT.
extern "C" void on_suspend(int) {
  const int saved_errno = errno;
  while (g_writer.test_and_set(std::memory_order_acquire)) {
    // Another thread's handler is finishing its update (it runs: the process was continued).
  }
  const std::int64_t t0 = monotonic_ns();
  write_state([&] { g_since_ns.store(t0, std::memory_order_relaxed); });
  g_writer.clear(std::memory_order_release);
  raise(SIGSTOP);  // returns after SIGCONT
  while (g_writer.test_and_set(std::memory_order_acquire)) {
  }
  const std::int64_t t1 = monotonic_ns();
  write_state([&] {
    g_suspended_ns.fetch_add(t1 - t0, std::memory_order_relaxed);
    g_since_ns.store(0, std::memory_order_relaxed);
  });
  g_writer.clear(std::memory_order_release);
  errno = saved_errno;
}

}  // namespace

RunClock::time_point RunClock::now() noexcept {
  std::uint64_t s0, s1;
  std::int64_t suspended, since, now_ns;
  do {
    s0 = g_seq.load(std::memory_order_acquire);
    suspended = g_suspended_ns.load(std::memory_order_relaxed);
    since = g_since_ns.load(std::memory_order_relaxed);
    now_ns = monotonic_ns();
    std::atomic_thread_fence(std::memory_order_acquire);
    s1 = g_seq.load(std::memory_order_relaxed);
  } while ((s0 & 1) != 0 || s0 != s1);
  return time_point(std::chrono::nanoseconds((since != 0 ? since : now_ns) - suspended));
}

void install_suspend_handler() {
  struct sigaction sa {};
  sa.sa_handler = on_suspend;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // reads and writes interrupted by the stop carry on
  sigaction(SIGTSTP, &sa, nullptr);
}

double suspended_seconds() {
  return 1e-9 * double(g_suspended_ns.load(std::memory_order_relaxed));
}

}  // namespace lbdem

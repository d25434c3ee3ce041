// The run clock (core/run_clock.hpp) leaves out a suspension by SIGTSTP, which the steady clock
// counts. A child process suspends itself; the parent holds it stopped for 0.3 s and continues it.
#include <catch2/catch.hpp>

#include <csignal>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "core/run_clock.hpp"

using namespace lbdem;

namespace {
// Kills and reaps the child if the test leaves early, so that no stopped process is left behind.
struct Child {
  pid_t pid = -1;
  ~Child() {
    if (pid > 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
  }
};
}  // namespace

TEST_CASE("the run clock leaves out a SIGTSTP suspension, which the steady clock counts",
          "[core]") {
  int fd[2];
  REQUIRE(pipe(fd) == 0);
  Child child;
  child.pid = fork();
  REQUIRE(child.pid >= 0);
  if (child.pid == 0) {
    // Child: only async-signal-safe calls and clock reads between fork and _exit.
    close(fd[0]);
    sigset_t tstp;
    sigemptyset(&tstp);
    sigaddset(&tstp, SIGTSTP);
    sigprocmask(SIG_UNBLOCK, &tstp, nullptr);  // a mask inherited from the test runner
    install_suspend_handler();
    const auto s0 = std::chrono::steady_clock::now();
    const auto r0 = RunClock::now();
    raise(SIGTSTP);
    const auto r1 = RunClock::now();
    const auto s1 = std::chrono::steady_clock::now();
    const double d[3] = {std::chrono::duration<double>(s1 - s0).count(),
                         std::chrono::duration<double>(r1 - r0).count(), suspended_seconds()};
    const bool ok = write(fd[1], d, sizeof d) == ssize_t(sizeof d);
    _exit(ok ? 0 : 1);
  }
  close(fd[1]);
  int status = 0;
  REQUIRE(waitpid(child.pid, &status, WUNTRACED) == child.pid);
  // Stopped by the handler's SIGSTOP, as SIGTSTP's default action would have stopped it.
  REQUIRE(WIFSTOPPED(status));
  REQUIRE(WSTOPSIG(status) == SIGSTOP);
  const double hold = 0.3;
  std::this_thread::sleep_for(std::chrono::duration<double>(hold));
  REQUIRE(kill(child.pid, SIGCONT) == 0);
  double d[3] = {0, 0, 0};
  pollfd p{fd[0], POLLIN, 0};
  const bool ready = poll(&p, 1, 20'000) == 1;  // 20 s: a hung child fails instead of hanging
  const bool got = ready && read(fd[0], d, sizeof d) == ssize_t(sizeof d);
  close(fd[0]);
  REQUIRE(got);
  REQUIRE(waitpid(child.pid, &status, 0) == child.pid);
  child.pid = -1;
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  const double steady = d[0], run = d[1], suspended = d[2];
  // The child was stopped at least `hold`: the steady clock counts all of it. What the run clock
  // keeps is the signal path outside the stop (microseconds); 0.05 s allows for a loaded CI
  // machine descheduling the child around the stop, and is a sixth of the hold.
  CHECK(steady >= hold);
  CHECK(suspended >= hold);
  CHECK(run >= 0);
  CHECK(run < 0.05);
  CHECK(steady - run == Approx(suspended).margin(0.05));
}

// The phase timers (core/phase_timer.hpp): laps book the time between them to their phase, the
// table's shares add up to the wall time given, and switched off nothing is booked. Against a
// stopwatch around the same laps (both read the run clock, the steady clock when nothing is
// suspended).
#include <catch2/catch.hpp>

#include <chrono>
#include <string>
#include <thread>

#include "core/phase_timer.hpp"
#include "core/timer.hpp"

using namespace lbdem;

TEST_CASE("phase timers book laps to their phases, and nothing when off", "[core]") {
  PhaseTimer& t = PhaseTimer::global();
  t.reset();
  t.enable(true);
  Stopwatch watch;
  {
    PhaseLap lap;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    lap.to(Phase::lbm_collide_stream);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    lap.to(Phase::dem_pair_contacts);
  }
  const double wall = watch.seconds();
  // Sleeps last at least what they ask; the laps together cannot exceed the stopwatch around them.
  CHECK(t.seconds(Phase::lbm_collide_stream) >= 0.020);
  CHECK(t.seconds(Phase::dem_pair_contacts) >= 0.010);
  CHECK(t.total() <= wall);
  CHECK(t.seconds(Phase::output) == 0.0);
  const std::string table = t.table(wall);
  CHECK(table.find("gas: stream-collide") != std::string::npos);
  CHECK(table.find("DEM: particle contacts") != std::string::npos);
  CHECK(table.find("output") == std::string::npos);  // phases without time are left out
  t.reset();
  t.enable(false);
  {
    PhaseLap lap;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    lap.to(Phase::output);
  }
  CHECK(t.total() == 0.0);
  t.enable(true);
}

// The rheometer scenario on small, coarse beds (l = 4, about 1,100 parcels): the torques on
// impeller, cup and floor balance the particles' angular momentum; +600 and -600 rpm give opposite
// mean torques; meshed and analytic blades give the same mean torque.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "core/config.hpp"
#include "scenarios/rheometer/rheometer.hpp"

using namespace lbdem;

namespace {

Config small_bed(const std::string& extra) {
  Config c = Config::from_file(std::string(LBDEM_SOURCE_DIR) +
                               "/scenarios/rheometer/presets/default.toml");
  for (const char* s : {"coarse_grain.size_factor=4", "rheometer.start=0.08", "run.end_time=0.3"})
    c.set_override(s);
  if (!extra.empty()) c.set_override(extra);
  return c;
}

struct Stats {
  double mean, error;  // mean and its standard error from block averages
};

// Mean drive torque over [t0, t1] and its standard error from 10 block means (blocks of 0.015 s,
// several times the torque's correlation time of a few blade passages of a parcel, ~ms).
Stats mean_torque(const std::string& extra, double t0, double t1) {
  scenarios::RheometerScenario sc(small_bed(extra));
  auto& s = sc.solver();
  const int blocks = 10;
  std::vector<double> sum(blocks, 0.0);
  std::vector<int> n(blocks, 0);
  while (s.time() < t1) {
    s.step();
    if (s.time() <= t0) continue;
    const int b = std::min(blocks - 1, static_cast<int>((s.time() - t0) / (t1 - t0) * blocks));
    sum[b] += sc.drive_torque(), ++n[b];
  }
  double m = 0, m2 = 0;
  for (int b = 0; b < blocks; ++b) m += sum[b] / n[b] / blocks;
  for (int b = 0; b < blocks; ++b) m2 += std::pow(sum[b] / n[b] - m, 2) / (blocks - 1);
  return {m, std::sqrt(m2 / blocks)};
}

}  // namespace

TEST_CASE("Rheometer: wall torques balance the particles' angular momentum", "[scenarios]") {
  // Velocity Verlet changes each particle's m x × v + I w by dt/2 (tau_n + tau_n+1) exactly (the
  // drift adds dt v × v = 0); contact torques between particles cancel pairwise (the arms a_i + a_j
  // equal the centre distance), gravity has no moment about the vertical axis, and each wall
  // receives exactly minus what its contacts put on the particle. So Delta L_z = -sum over steps
  // of dt/2 (T_n + T_n+1) of all walls, to round-off: 1e-9 of the torque impulse allows 1e5 steps
  // of 1e-14 relative rounding.
  scenarios::RheometerScenario sc(small_bed("run.end_time=0.12"));
  auto& s = sc.solver();
  const auto wall_sum = [&] {
    double t = 0;
    for (const auto& w : s.walls()) t += w.torque.z();
    return t;
  };
  for (int k = 0; k < 2; ++k) s.step();
  const double l0 = sc.angular_momentum();
  double prev = wall_sum(), impulse = 0, scale = 0;
  const double dt = s.settings().dt;
  while (s.time() < 0.12) {  // settling, then the first 0.02 s of spin-up and rotation
    s.step();
    const double now = wall_sum();
    impulse += 0.5 * dt * (prev + now);
    scale += 0.5 * dt * (std::abs(prev) + std::abs(now));
    prev = now;
  }
  CHECK(std::abs(sc.drive_torque()) > 0);  // the impeller turns in the bed
  INFO("dL " << sc.angular_momentum() - l0 << " impulse " << impulse << " scale " << scale);
  CHECK(std::abs(sc.angular_momentum() - l0 + impulse) < 1e-9 * scale);
}

TEST_CASE("Rheometer: +600 and -600 rpm give opposite mean torques", "[scenarios][slow]") {
  // The set-up is mirror symmetric (the jittered bed only statistically): the mean drive torques
  // must agree in magnitude within 3 combined standard errors, and each must be well above its
  // error (else the test could not fail).
  const Stats plus = mean_torque("rheometer.rpm=600", 0.15, 0.3);
  const Stats minus = mean_torque("rheometer.rpm=-600", 0.15, 0.3);
  INFO("+600: " << plus.mean << " +- " << plus.error << ", -600: " << minus.mean << " +- "
                << minus.error);
  CHECK(plus.mean > 5 * plus.error);
  CHECK(-minus.mean > 5 * minus.error);
  CHECK(std::abs(plus.mean + minus.mean) < 3 * std::hypot(plus.error, minus.error));
}

TEST_CASE("Rheometer: meshed and analytic blades give the same mean torque", "[scenarios][slow]") {
  // The cuboid mesh and the analytic cuboid give the same contacts to rounding
  // (test_box_wall.cpp); the beds then diverge chaotically, so the means agree only within the
  // statistical error (3 combined standard errors).
  const Stats mesh = mean_torque("rheometer.impeller=mesh", 0.15, 0.3);
  const Stats box = mean_torque("rheometer.impeller=analytic", 0.15, 0.3);
  INFO("mesh: " << mesh.mean << " +- " << mesh.error << ", analytic: " << box.mean << " +- "
                << box.error);
  CHECK(mesh.mean > 5 * mesh.error);
  CHECK(std::abs(mesh.mean - box.mean) < 3 * std::hypot(mesh.error, box.error));
}

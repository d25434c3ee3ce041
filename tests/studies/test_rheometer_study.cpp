// The rheometer study's torque summary on a synthetic torque of known statistics: a spin-up peak,
// then a steady mean with a sinusoidal blade-passage fluctuation.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/types.hpp"
#include "studies/rheometer_study.hpp"

using namespace lbdem;

TEST_CASE("Rheometer study: torque summary of a signal with known mean, amplitude and peak",
          "[studies]") {
  // 600 rpm from t = 0.2 s: the steady window starts one revolution (0.1 s) later. Samples every
  // 1 ms to 1.2 s. Steady part: 0.05 + 0.01 sin(2 pi 20 t) N m (20 Hz, whole periods per 0.05 s
  // block); a 0.1 N m bump in the first revolution sets the peak.
  std::vector<double> t, q;
  for (int k = 0; k <= 1200; ++k) {
    const double s = 1e-3 * k;
    double v = s > 0.2 ? 0.05 + 0.01 * std::sin(2 * kPi * 20 * s) : 0.0;
    if (s > 0.22 && s <= 0.24) v += 0.1;
    t.push_back(s), q.push_back(v);
  }
  const auto r = studies::summarize_torque(t, q, 0.2, 600);
  // Whole periods per sample window: the mean and sd are exact up to the sampling of the sine
  // (1e-12 on the mean; sd = 0.01 / sqrt2 within 0.1 % for 50 samples per period).
  CHECK(r.steady == Approx(0.05).margin(1e-12));
  CHECK(r.fluctuation == Approx(0.01 / std::sqrt(2.0)).epsilon(1e-3));
  // Every 0.05 s block holds whole periods, so the block means are equal: zero standard error.
  CHECK(r.steady_err < 1e-12);
  CHECK(r.blocks == 18);  // (1.2 - 0.3) / 0.05
  // Peak: the largest 0.01 s block mean in the first revolution is the bump plus the sine's mean.
  // A 10 ms block holds 1/5 of a sine period, whose mean is at most 0.0094 N m: 6.2 % of 0.15.
  CHECK(r.peak == Approx(0.15).epsilon(0.07));
}

// Two-parcel head-on collisions with the DEM engine at l = 1, 2, 4: the rules that promise it give
// the same restitution and delta_max/d and a contact time ~ l; stiffness_only shows its drift.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "cg_setup.hpp"
#include "dem/contact/hertz_mindlin.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"

using namespace lbdem;
using cg::ScalingRule;

namespace {

struct Outcome {
  double e;       // measured restitution
  double t_c;     // measured contact duration [s]
  double dmax_d;  // largest overlap / parcel diameter [-]
  long steps;     // steps in contact
};

// Parcels of the rule at size factor l approach at relative speed v (no gravity, no friction).
// The step is dt1 (50 steps per original contact) times the rule's time-step factor, and the
// initial gap is 1 um times l, so that the run at l is the one at l = 1 in the units d and t_c.
Outcome collide(ScalingRule rule, double l, double v, double dt1, double e = 0.8) {
  const auto m = test::hdpe(e, 0.0, 0.0);
  const auto p = cg::scale(m, test::kSeedRadius, test::cg_settings(rule, l));
  auto s = test::settings(dt1 * p.time_step_factor);
  s.contact.normal = test::law_of(rule);
  dem::DemSolver solver(s, {cg::parcel_material(m, p)});
  const double r = p.radius, gap = 1e-6 * l;
  solver.add_particle(Vec3(-r - gap, 0, 0), Vec3(0.5 * v, 0, 0), r, 0);
  solver.add_particle(Vec3(r + gap, 0, 0), Vec3(-0.5 * v, 0, 0), r, 0);
  const auto& x = solver.particles().x;
  double dmax = 0;
  long in = 0;
  bool seen = false;
  for (long k = 0; k < 100000; ++k) {
    solver.step();
    const bool c = solver.contacts_pp() > 0;
    if (c) seen = true, ++in;
    dmax = std::max(dmax, 2 * r - (x[1] - x[0]).norm());
    if (seen && !c) break;
  }
  const auto& vel = solver.particles().v;
  const int a = x[0].x() < x[1].x() ? 0 : 1;  // the left one, should the solver reorder them
  return {(vel[1 - a].x() - vel[a].x()) / v, in * s.dt, dmax / (2 * r), in};
}

// delta_max of the damped linear oscillator at approach speed v: delta(t) = (v/w_d) exp(-zeta w0
// t) sin(w_d t) peaks at tan(w_d t) = sqrt(1 - zeta^2)/zeta, giving delta_max = (v/w0) exp(-zeta /
// sqrt(1 - zeta^2) atan(sqrt(1 - zeta^2)/zeta)).
double linear_dmax(double k, double m_star, double e, double v) {
  const double z = std::abs(dem::restitution_beta(e)), q = std::sqrt(1 - z * z);
  return v / std::sqrt(k / m_star) * std::exp(-z / q * std::atan(q / z));
}

}  // namespace

TEST_CASE("CG collisions: linear_similarity keeps e and delta_max/d, t_c ~ l", "[coarse_grain]") {
  const test::OneThread one_thread;
  const double v = 0.5;  // [m/s], a typical impeller-driven impact
  const auto m = test::hdpe(0.8, 0.0, 0.0);
  const double mass = m.density * 4.0 / 3.0 * kPi * std::pow(test::kSeedRadius, 3);
  const double gamma = 2 * std::abs(dem::restitution_beta(0.8)) * std::sqrt(0.5 * mass * 1000);
  const double tc1 = dem::linear_contact_time(1000, gamma, 0.5 * mass);
  const auto o1 = collide(ScalingRule::linear_similarity, 1, v, tc1 / 50);
  for (double l : {1.0, 2.0, 4.0}) {
    const auto o = collide(ScalingRule::linear_similarity, l, v, tc1 / 50);
    INFO("l = " << l << ": e " << o.e << ", t_c " << o.t_c << ", delta_max/d " << o.dmax_d);
    // 1 %: velocity Verlet at 50 steps per contact (tests/dem/test_restitution.cpp).
    CHECK(o.e == Approx(0.8).epsilon(0.01));
    // Contact duration resolved to one step of 50: 2 %.
    CHECK(o.t_c / l == Approx(tc1).epsilon(0.02));
    // Peak overlap sampled once per step at dt = t_c/50: the sampled peak lies within
    // (pi/50)^2/2 = 0.2 % of the true one, and Verlet's amplitude error is O((dt/t_c)^2): 1 %.
    CHECK(o.dmax_d ==
          Approx(linear_dmax(1000, 0.5 * mass, 0.8, v) / (2 * test::kSeedRadius)).epsilon(0.01));
    // Across l the runs solve the same dimensionless problem (every term of m* x'' = -k x -
    // gamma x' scales as l^2 with x ~ l, t ~ l; gap and step scaled too), and l is a power of two,
    // so they differ only by rounding: 1e-9.
    CHECK(o.steps == o1.steps);
    CHECK(o.e == Approx(o1.e).epsilon(1e-9));
    CHECK(o.dmax_d == Approx(o1.dmax_d).epsilon(1e-9));
  }
}

TEST_CASE("CG collisions: hertz keeps e and delta_max/d, t_c ~ l", "[coarse_grain]") {
  const test::OneThread one_thread;
  const double v = 0.5;
  const auto m = test::hdpe(0.8, 0.0, 0.0);
  const double r = test::kSeedRadius;
  const double mass = m.density * 4.0 / 3.0 * kPi * r * r * r;
  const auto mp = dem::mix(m, m);
  const double tc1 = dem::hertz_contact_time(mp.e_star, 0.5 * r, 0.5 * mass, v);
  const auto o1 = collide(ScalingRule::hertz, 1, v, tc1 / 50);
  for (double l : {1.0, 2.0, 4.0}) {
    const auto o = collide(ScalingRule::hertz, l, v, tc1 / 50);
    INFO("l = " << l << ": e " << o.e << ", t_c " << o.t_c << ", delta_max/d " << o.dmax_d);
    // 1 %: as for the linear law (Tsuji damping gives e exactly in the continuous limit).
    CHECK(o.e == Approx(0.8).epsilon(0.01));
    // Same-problem argument as for the linear law (E* sqrt(R*) delta^{3/2} ~ l^2 with the Tsuji
    // dashpot sqrt(m* k_n) v ~ l^2 too): t_c ~ l to the step, e and delta_max/d to 1e-9.
    CHECK(o.steps == o1.steps);
    CHECK(o.e == Approx(o1.e).epsilon(1e-9));
    CHECK(o.dmax_d == Approx(o1.dmax_d).epsilon(1e-9));
  }
  // Elastic contacts at l = 1 and 4 against closed forms (the damped Hertz contact has none): peak
  // overlap (15 m* v^2 / (16 E* sqrt(R*)))^{2/5} from energy conservation, 1 % (peak sampled once
  // per step, Verlet amplitude error, as for the linear law); contact time 2.868 (m*^2 / (R* E*^2
  // v))^{1/5} (Johnson 1985) times l, within one step of 50 (2 %).
  const double dmax =
      std::pow(15 * 0.5 * mass * v * v / (16 * mp.e_star * std::sqrt(0.5 * r)), 0.4);
  for (double l : {1.0, 4.0}) {
    const auto o = collide(ScalingRule::hertz, l, v, tc1 / 50, 1.0);
    CHECK(o.dmax_d == Approx(dmax / (2 * r)).epsilon(0.01));
    CHECK(o.t_c / l == Approx(tc1).epsilon(0.02));
  }
}

TEST_CASE("CG collisions: stiffness_only drifts to the restitution of zeta/l^2", "[coarse_grain]") {
  const test::OneThread one_thread;
  const double v = 0.5;
  const auto m = test::hdpe(0.8, 0.0, 0.0);
  const double mass = m.density * 4.0 / 3.0 * kPi * std::pow(test::kSeedRadius, 3);
  const double gamma = 2 * std::abs(dem::restitution_beta(0.8)) * std::sqrt(0.5 * mass * 1000);
  const double tc1 = dem::linear_contact_time(1000, gamma, 0.5 * mass);
  // Hand-derived drift from e = 0.8 (test_scaling_rules.cpp): 0.91670 at l = 1.6, 0.94587 at 2.
  // 1 %: velocity Verlet at 50 steps per contact.
  CHECK(collide(ScalingRule::stiffness_only, 1.6, v, tc1 / 50).e == Approx(0.91670).epsilon(0.01));
  CHECK(collide(ScalingRule::stiffness_only, 2.0, v, tc1 / 50).e == Approx(0.94587).epsilon(0.01));
}

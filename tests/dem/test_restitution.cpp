// Binary normal collisions against the analytic restitution and contact duration.
#include <catch2/catch.hpp>

#include "dem/contact/hertz_mindlin.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/registry.hpp"
#include "dem/time_step.hpp"
#include "helpers/dem_setup.hpp"

using namespace lbdem;

namespace {

struct Outcome {
  double e;             // measured restitution
  double t_c;           // measured contact duration [s]
  double t_pred;        // predicted (analytic) duration [s]
  double energy_error;  // |stored + dissipated - initial| / initial
};

// Two equal spheres approaching head-on along x at +-v/2, no gravity, no friction.
Outcome collide(const std::string& law, double e, double v, double steps_per_contact) {
  const double r = 5e-4;
  auto mat = test::glass(e, 0.0);
  dem::ContactSettings cs;
  cs.normal = law;
  const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
  const auto mp = dem::mix(mat, mat);
  // The law's own contact time (linear: pi / sqrt(k/m* - (gamma/2m*)^2); Hertz: Johnson's
  // 2.868 (m*^2/(R* E*^2 v))^(1/5)), as the time-step check takes it.
  const double t_pred =
      std::visit([&](auto n) { return decltype(n)::contact_time(mp, 0.5 * r, 0.5 * m, v); },
                 dem::normal_law(law));
  auto s = test::settings(t_pred / steps_per_contact);
  s.contact = cs;
  dem::DemSolver solver(s, {mat});
  const double gap = 1e-6;
  solver.add_particle(Vec3(-r - gap, 0, 0), Vec3(0.5 * v, 0, 0), r, 0);
  solver.add_particle(Vec3(r + gap, 0, 0), Vec3(-0.5 * v, 0, 0), r, 0);
  const double e0 = solver.energy().stored();
  const long n = test::run_through_contact(solver);
  const auto& p = solver.particles();
  const double v_after = p.v[1].x() - p.v[0].x();
  const auto en = solver.energy();
  return {v_after / v, n * s.dt, t_pred, std::abs(en.stored() + en.dissipated() - e0) / e0};
}

}  // namespace

TEST_CASE("linear spring-dashpot restitution and contact time", "[dem][physics]") {
  for (double e : {0.3, 0.5, 0.8, 0.95}) {
    const auto o = collide("linear", e, 1.0, 50);
    INFO("e = " << e << " measured " << o.e);
    // 1 %: the tolerance at t_c/50; with the end-of-step predicted velocity the dashpot is
    // second-order consistent, so the discrete e differs from the closed form by O((dt/t_c)^2).
    CHECK(o.e == Approx(e).epsilon(0.01));
    // The contact is resolved to one step: duration within one step (2 % at 50 steps) of
    // pi / sqrt(k/m* - (gamma/2m*)^2).
    CHECK(o.t_c == Approx(o.t_pred).epsilon(0.02));
  }
}

TEST_CASE("Hertz-Mindlin (Tsuji damping) restitution and contact time", "[dem][physics]") {
  for (double e : {0.3, 0.5, 0.8, 0.95}) {
    const auto o = collide("hertz_mindlin", e, 1.0, 50);
    INFO("e = " << e << " measured " << o.e << " energy error " << o.energy_error);
    CHECK(o.e == Approx(e).epsilon(0.01));
  }
  // Elastic contact duration against 2.868 (m*^2/(R* E*^2 v))^(1/5) (Johnson 1985), 2 %: one step
  // of 50 is 2 %.
  const auto o = collide("hertz_mindlin", 1.0, 1.0, 50);
  CHECK(o.t_c == Approx(o.t_pred).epsilon(0.02));
  CHECK(o.e == Approx(1.0).epsilon(1e-3));
}

TEST_CASE(
    "every registered normal law: the time-step check takes its own contact time, and an "
    "elastic collision lasts that long",
    "[dem][physics]") {
  // The closed forms themselves are checked against the laws' papers above; here each law of the
  // registry (dem/contact/registry.hpp, NormalVariant) is checked to be the one the time-step
  // estimate asks: a law added to the list with a wrong or missing contact time fails here. The
  // collision is resolved with 50 steps: its duration within one step, 2 %.
  const double r = 5e-4, v = 1.0;
  const auto mat = test::glass(1.0, 0.0);
  const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (
        [&] {
          using Law = std::variant_alternative_t<I, dem::NormalVariant>;
          const std::string name(Law::name);
          CAPTURE(name);
          CHECK(dem::kNormalLaws[I] == name);
          dem::ContactSettings cs;
          cs.normal = name;
          const double t_law = Law::contact_time(dem::mix(mat, mat), 0.5 * r, 0.5 * m, v);
          CHECK(dem::time_scales(cs, {mat}, {}, r, v).contact_time == t_law);
          const auto o = collide(name, 1.0, v, 50);
          CHECK(o.t_pred == t_law);
          CHECK(o.t_c == Approx(t_law).epsilon(0.02));
        }(),
        ...);
  }
  (std::make_index_sequence<std::variant_size_v<dem::NormalVariant>>{});
}

TEST_CASE("a damped collision closes its energy budget to second order in the step",
          "[dem][physics][energy]") {
  // Stored (kinetic + elastic) plus dissipated energy against the energy before the contact.
  // Velocity Verlet with the dashpot on the predicted velocity is second-order: it gives
  // about 1e-3 for one damped Hertz collision at t_c/50, falling 4x per halving of the step.
  // Bounds at t_c/50: 2e-3 for Hertz (twice that figure). There is no figure for the linear
  // dashpot, whose error grows faster with the damping: its 4e-3 is a regression bound set from
  // this code's own 2.87e-3 at e = 0.3 with 40 % margin (measured: Hertz 1.36e-3, 1.09e-3, 5.2e-4
  // and linear 2.87e-3, 1.54e-3, 5.1e-4 at e = 0.3, 0.5, 0.8); the order check is what ties both
  // laws to the reference. On halving
  // the step, at least 3x less: second order gives 4x less the higher-order terms
  // (measured 4.3-4.9x); a first-order error (a dashpot on the stale velocity, an account half a
  // step off) gives 2x.
  for (const char* law : {"hertz_mindlin", "linear"})
    for (double e : {0.3, 0.5, 0.8}) {
      const auto coarse = collide(law, e, 1.0, 50), fine = collide(law, e, 1.0, 100);
      INFO(law << " e = " << e << ": energy error " << coarse.energy_error << " at t_c/50, "
               << fine.energy_error << " at t_c/100");
      CHECK(coarse.energy_error < (std::string(law) == "linear" ? 4e-3 : 2e-3));
      CHECK(coarse.energy_error > 3 * fine.energy_error);
    }
}

// Energy: (1) elastic frictionless collisions: the energy error of one collision comes from where
// the contact's start and end fall inside a step. The linear law's force has a kink there (F' jumps
// by k): local error O(dt^3), 8x per halving. Hertz's F ~ delta^{3/2} has an unbounded second
// derivative at touch: O(dt^{5/2}), 2^{5/2} = 5.7x per halving (measured 5.84 and 5.90 from t_c/50
// to t_c/200), so the ">= 6x" holds for the linear law only; (2) the budget of a
// damped, frictional settling bed closes at second order, as velocity Verlet allows
// (docs/physics.md).
#include <catch2/catch.hpp>
#include <cmath>

#include "dem/contact/hertz_mindlin.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/insertion.hpp"
#include "helpers/dem_setup.hpp"

using namespace lbdem;

namespace {
// rms relative energy error of n head-on elastic collisions with random phase (the initial gap is a
// random fraction of one step's approach).
double rms_collision_error(const std::string& law, double steps_per_contact, int n) {
  const double r = 5e-4, v = 1.0;
  const auto mat = test::glass(1.0, 0.0);
  const auto mp = dem::mix(mat, mat);
  const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
  const double tc = law == "linear" ? dem::linear_contact_time(mp.stiffness, 0, 0.5 * m)
                                    : dem::hertz_contact_time(mp.e_star, 0.5 * r, 0.5 * m, v);
  auto s = test::settings(tc / steps_per_contact);
  s.contact.normal = law;
  s.domain.lo = Vec3(-2e-3, -2e-3, -2e-3);
  s.domain.hi = Vec3(2e-3, 2e-3, 2e-3);
  std::mt19937_64 rng(11);
  double sum2 = 0;
  for (int k = 0; k < n; ++k) {
    dem::DemSolver sol(s, {mat});
    const double gap = (0.5 + dem::uniform01(rng)) * v * s.dt;
    sol.add_particle(Vec3(-r - gap / 2, 0, 0), Vec3(0.5 * v, 0, 0), r, 0);
    sol.add_particle(Vec3(r + gap / 2, 0, 0), Vec3(-0.5 * v, 0, 0), r, 0);
    const double e0 = sol.energy().kinetic();
    test::run_through_contact(sol);
    const double err = sol.energy().kinetic() / e0 - 1;
    sum2 += err * err;
  }
  return std::sqrt(sum2 / n);
}

// |stored + dissipated - injected| / dissipated after a bed of 200 beads has settled.
double bed_budget_error(double steps_per_contact) {
  const double r = 1e-3;
  auto mat = test::glass(0.5, 0.5);
  mat.youngs_modulus = 5e7;
  const auto mp = dem::mix(mat, mat);
  const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
  const double tc = dem::hertz_contact_time(mp.e_star, 0.5 * r, 0.5 * m, 1.0);
  auto s = test::settings(tc / steps_per_contact, Vec3(0, 0, -9.81));
  s.domain.lo = Vec3(0, 0, 0);
  s.domain.hi = Vec3(0.02, 0.02, 0.06);
  dem::DemSolver sol(s, {mat});
  for (int a = 0; a < 2; ++a)
    for (int side = 0; side < 2; ++side) {
      dem::Wall w = test::floor_wall();
      dem::PlaneWall p;
      p.point = side ? s.domain.hi : s.domain.lo;
      p.normal = Vec3::Zero();
      p.normal[a] = side ? -1 : 1;
      w.shape = p;
      sol.add_wall(w);
    }
  sol.add_wall(test::floor_wall(0));
  std::mt19937_64 rng(5);
  dem::FillRequest req;
  req.lo = Vec3(0, 0, 0.01);
  req.hi = Vec3(0.02, 0.02, 0.06);
  req.count = 200;
  req.radius.kind = "uniform";
  req.radius.min = 0.9 * r;
  req.radius.max = r;
  for (const auto& p : dem::random_fill(req, {}, rng)) sol.add_particle(p.x, Vec3::Zero(), p.r, 0);
  const double e0 = sol.energy().stored();
  const long steps = std::lround(0.25 / s.dt);  // falls 5 cm in 0.1 s, then settles
  for (long k = 0; k < steps; ++k) sol.step();
  const auto e = sol.energy();
  REQUIRE(e.kinetic() < 1e-3 * e.dissipated());  // settled
  return std::abs(e.stored() + e.dissipated() - e.injected(e0)) / e.dissipated();
}
}  // namespace

TEST_CASE("elastic collisions: rms energy error per collision and its order in dt",
          "[dem][physics][energy]") {
  for (const std::string law : {"linear", "hertz_mindlin"}) {
    const double e50 = rms_collision_error(law, 50, 1000),
                 e100 = rms_collision_error(law, 100, 1000);
    INFO(law << ": rms error at t_c/50: " << e50 << ", at t_c/100: " << e100);
    CHECK(e50 < 2e-4);  // the bound at t_c/50
    // Third order (8x) for the linear law, 5/2 order (5.66x) for Hertz; each bound leaves ~5 % for
    // the sampling of 1000 random phases.
    CHECK(e50 / e100 >= (law == "linear" ? 7.5 : 5.4));
  }
}

TEST_CASE("settling-bed energy budget closes at second order", "[dem][physics][energy][slow]") {
  const double e50 = bed_budget_error(50), e100 = bed_budget_error(100);
  INFO("budget error / dissipated at t_c/50: " << e50 << ", at t_c/100: " << e100);
  CHECK(e50 < 2e-3);         // the bound at t_c/50
  CHECK(e50 / e100 >= 3.0);  // second order gives 4; 3 allows for the chaotic bed's different paths
}

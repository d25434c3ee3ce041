// Bitwise equality of the particle state, energy totals and wall loads for 1, 2 and 4 threads
// (per-contact forces, ordered gather, fixed-block sums).
#include <omp.h>

#include <catch2/catch.hpp>
#include <cstring>

#include "dem/insertion.hpp"
#include "helpers/dem_setup.hpp"

using namespace lbdem;

namespace {
struct State {
  std::vector<Vec3> x, v, w;
  double energy[4];
  Vec3 floor_force;
};

State run(int threads) {
  omp_set_num_threads(threads);
  const double r = 5e-4;
  auto s = test::settings(2e-6, Vec3(0, 0, -9.81));
  s.domain.lo = Vec3(0, 0, 0);
  s.domain.hi = Vec3(0.01, 0.01, 0.02);
  s.domain.periodic = {true, true, false};
  dem::DemSolver sol(s, {test::glass(0.5, 0.5)});
  sol.add_wall(test::floor_wall(0));
  std::mt19937_64 rng(7);
  dem::FillRequest req;
  req.lo = Vec3(0, 0, 0);
  req.hi = Vec3(0.01, 0.01, 0.02);
  req.count = 800;
  req.radius.kind = "uniform";
  req.radius.min = 0.8 * r;
  req.radius.max = r;
  for (const auto& p : dem::random_fill(req, {}, rng))
    sol.add_particle(p.x, Vec3(0.1, 0, -0.2), p.r, 0);
  for (int k = 0; k < 3000; ++k) sol.step();
  const auto e = sol.energy();
  State st{sol.particles().x,
           sol.particles().v,
           sol.particles().omega,
           {e.kinetic(), e.elastic, e.sliding, e.normal_damping},
           sol.walls()[0].force};
  // Ids order the comparison: the particle order itself is deterministic too, so compare as is.
  return st;
}

bool same(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}
}  // namespace

TEST_CASE("bitwise identical results on 1, 2 and 4 threads", "[dem][determinism][slow]") {
  const State a = run(1), b = run(2), c = run(4);
  omp_set_num_threads(omp_get_num_procs());
  REQUIRE(a.x.size() == 800);
  // Every field against the 1-thread run, for both other counts.
  for (const State* o : {&b, &c}) {
    CHECK(same(a.x, o->x));
    CHECK(same(a.v, o->v));
    CHECK(same(a.w, o->w));
    CHECK(std::memcmp(a.energy, o->energy, sizeof a.energy) == 0);
    CHECK(std::memcmp(a.floor_force.data(), o->floor_force.data(), sizeof(Vec3)) == 0);
  }
  CHECK(a.energy[2] > 0);  // the run had sliding contacts: the comparison is not vacuous
}

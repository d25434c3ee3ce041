// Momentum balance through a periodic array of cubes (a simple cubic array of obstacles), driven
// by a uniform body force: at steady state the fluid's momentum is constant, so the
// momentum-exchange force on the cubes must equal the total body force on the fluid,
// N_fluid F (Ladd 1994, JFM 271, 285: momentum exchange is exact bookkeeping of bounce-back).
#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>

using namespace lbdem;
using namespace lbdem::lbm;

TEST_CASE("steady drag on a cube array balances the body force", "[lbm]") {
  const int n = 8, side = 4;
  const Vec3 force(2e-6, 1e-6, 0);
  for (const CollisionModel& op :
       {CollisionModel(Trt::from_tau(1.0)), CollisionModel(Bgk::from_tau(1.2))}) {
    LbmSettings s;
    s.nx = s.ny = s.nz = n;
    s.collision = op;
    s.body_force = force;
    LbmSolver lbm(s);
    const int cube = lbm.add_body("cube");
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) lbm.set_cell(x + 2, y + 2, z + 2, cube);
    const double fluid_cells = n * n * n - side * side * side;
    // Run to steady state: the mean flow relaxes at a rate set by the (unknown) drag coefficient
    // of the array, so iterate until the force changes by < 1e-11 of itself per 100 steps (its
    // round-off floor is about 1e-12).
    const Vec3 total = fluid_cells * force;
    Vec3 last = Vec3::Zero();
    long steps = 0;
    for (; steps < 100000; steps += 100) {
      for (int t = 0; t < 100; ++t) lbm.step();
      if ((lbm.wall_force(cube) - last).norm() < 1e-11 * total.norm()) break;
      last = lbm.wall_force(cube);
    }
    const Vec3 drag = lbm.wall_force(cube);
    INFO("drag " << drag.transpose() << " body force " << total.transpose() << " after " << steps);
    // 1e-8: the balance is exact at steady state. What is left is round-off and the transient: with
    // a change below 1e-11 per 100 steps, a geometric decay leaves 1e-11 / (1 - r) for a ratio r
    // per 100 steps, below 1e-8 for any r < 0.999.
    CHECK((drag - total).norm() < 1e-8 * total.norm());
  }
}

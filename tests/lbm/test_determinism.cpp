// Equivalence test (not validation): the populations and wall forces after a run are bitwise the
// same at 1 and 2 OpenMP threads.
#include <omp.h>

#include <catch2/catch.hpp>

#include "lbm/lbm_solver.hpp"

#include <cmath>
#include <cstring>
#include <vector>

using namespace lbdem;
using namespace lbdem::lbm;

namespace {

struct Snapshot {
  std::vector<double> pdf;
  std::vector<Vec3> forces;  // force and torque of every body
  std::vector<Vec3> velocity;
};

// Walls, a moving lid, a solid block, TRT, a uniform and a per-cell force: every code path; with
// les_porous the regularized LES operator, the porous-medium policy (eps, Darcy, Forchheimer) and
// the wall function on the block and the floor.
// With restore_at >= 0 the populations are saved after that many steps (stored_slots), scrambled
// by a fresh initialization and loaded back (load_state), as a checkpoint and resume do.
Snapshot run(int threads, int steps, bool les_porous = false,
             Precision storage = Precision::float64, int restore_at = -1) {
  omp_set_num_threads(threads);
  LbmSettings s;
  s.nx = 24;
  s.ny = 18;
  s.nz = 14;
  s.faces[4].kind = s.faces[5].kind = FaceKind::wall;
  s.faces[5].wall_velocity = Vec3(0.04, 0, 0);
  s.collision = Trt::from_tau(0.7);
  if (les_porous) s.collision = RegularizedLes::from_tau(0.51, 0.15);
  s.body_force = Vec3(1e-6, 0, -2e-6);
  s.precision = storage;
  LbmSolver lbm(s);
  lbm.initialize([](int x, int y, int z, double& rho, Vec3& u) {
    rho = 1.0 + 0.01 * std::sin(0.3 * x + 0.2 * y);
    u = Vec3(0.02 * std::cos(0.4 * z), 0.01 * std::sin(0.5 * x), 0);
  });
  const int block = lbm.add_body("block");
  for (int z = 4; z < 8; ++z)
    for (int y = 6; y < 9; ++y)
      for (int x = 3; x < 7; ++x) lbm.set_cell(x, y, z, block);
  lbm.enable_force_field();
  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x)
        lbm.set_cell_force(x, y, z, Vec3(1e-6 * std::sin(x + y), 0, 0));
  if (les_porous) {
    lbm.enable_porosity();
    for (int z = 0; z < s.nz; ++z)
      for (int y = 0; y < s.ny; ++y)
        for (int x = 0; x < s.nx; ++x)
          lbm.set_cell_porosity(x, y, z, 0.6 + 0.3 * std::cos(0.2 * x * y), 1e-3 * (z % 3));
    lbm.set_forchheimer(0.5);
    lbm.set_body_origin(block, Vec3(4.5, 7, 5.5));
    lbm.set_wall_function(block, true);  // and the wall function's per-cell slip
    lbm.set_wall_function(lbm.face_body(4), true);
  }
  for (int t = 0; t < steps; ++t) {
    if (t == restore_at) {
      const std::vector<double> slots = lbm.stored_slots();
      const AaState state = lbm.state();
      const long done = lbm.steps();
      lbm.initialize([](int, int, int, double& rho, Vec3& u) {
        rho = 1.1;
        u = Vec3(0.01, 0.02, 0.03);
      });
      lbm.load_state(slots, state, done);
    }
    lbm.step();
  }
  Snapshot snap;
  snap.pdf = lbm.stored_slots();
  lbm.velocity(snap.velocity);
  for (int b = 1; b <= lbm.body_count(); ++b) {
    snap.forces.push_back(lbm.wall_force(b));
    snap.forces.push_back(lbm.wall_torque(b));
  }
  return snap;
}

/// The run at 1 and at 2 threads, checked bitwise equal; returns the 1-thread snapshot.
Snapshot run_and_compare(bool les_porous, Precision storage = Precision::float64) {
  const int saved = omp_get_max_threads();
  const Snapshot one = run(1, 41, les_porous, storage);
  const Snapshot two = run(2, 41, les_porous, storage);
  omp_set_num_threads(saved);
  REQUIRE(one.pdf.size() == two.pdf.size());
  CHECK(std::memcmp(one.pdf.data(), two.pdf.data(), one.pdf.size() * sizeof(double)) == 0);
  REQUIRE(one.forces.size() == two.forces.size());
  for (std::size_t b = 0; b < one.forces.size(); ++b)
    CHECK(std::memcmp(one.forces[b].data(), two.forces[b].data(), 3 * sizeof(double)) == 0);
  return one;
}

}  // namespace

TEST_CASE("LBM populations and wall forces are bitwise the same at 1 and 2 threads", "[lbm]") {
  const Snapshot one = run_and_compare(false);
  // The block is the third body after the two walls, and it carries load.
  CHECK(one.forces.size() == 6);
  CHECK(one.forces[4].norm() > 0);
}

TEST_CASE("LES operator, porous medium and torques are bitwise the same at 1 and 2 threads",
          "[lbm]") {
  const Snapshot one = run_and_compare(true);
  CHECK(one.forces[5].norm() > 0);  // the block's torque about its centre
}

TEST_CASE("Float populations are bitwise the same at 1 and 2 threads, and resume exactly",
          "[lbm]") {
  const Snapshot one = run_and_compare(true, Precision::float32);
  CHECK(one.forces[5].norm() > 0);
  const int saved = omp_get_max_threads();
  // Saved and loaded back mid-run (after an odd step: the swapped AA state), the run goes on
  // bitwise as if it never stopped.
  const Snapshot resumed = run(1, 41, true, Precision::float32, 17);
  CHECK(std::memcmp(one.pdf.data(), resumed.pdf.data(), one.pdf.size() * sizeof(double)) == 0);
  for (std::size_t b = 0; b < one.forces.size(); ++b)
    CHECK(std::memcmp(one.forces[b].data(), resumed.forces[b].data(), 3 * sizeof(double)) == 0);
  // The same run in double: every code path (LES, porous form, force field, walls, moving lid,
  // wall function) gives the double velocities to float round-off. Speeds are up to about 0.05;
  // 41 steps each round every stored deviation (|f - w| <= about 0.2 w) to 2^-24 of itself, at
  // most 41 * 0.2 * 6e-8 / 3 = 1.6e-7 in u if every rounding went one way. A population read or
  // written without its w shift would be off by w_q >= 1/36 (an error of order 1e-2 in u).
  // Measured 1.5e-9.
  const Snapshot dbl = run(1, 41, true, Precision::float64);
  omp_set_num_threads(saved);
  double du = 0, umax = 0;
  for (std::size_t c = 0; c < dbl.velocity.size(); ++c) {
    du = std::max(du, (one.velocity[c] - dbl.velocity[c]).norm());
    umax = std::max(umax, dbl.velocity[c].norm());
  }
  INFO("largest velocity difference float - double " << du << " (largest speed " << umax << ")");
  CHECK(umax > 0.02);
  CHECK(du < 2e-7);
}

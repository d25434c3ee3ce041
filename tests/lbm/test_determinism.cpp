// Equivalence test (not validation): the populations and wall forces after a run are bitwise the
// same at 1 and 2 OpenMP threads (STYLE 5, 6).
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
};

// Walls, a moving lid, a solid block, TRT, a uniform and a per-cell force: every code path; with
// les_porous the regularized LES operator, the porous-medium policy (eps, Darcy, Forchheimer) and
// the wall function on the block and the floor.
Snapshot run(int threads, int steps, bool les_porous = false) {
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
  for (int t = 0; t < steps; ++t) lbm.step();
  Snapshot snap;
  snap.pdf.assign(lbm.pdf().data(), lbm.pdf().data() + lbm.pdf().size());
  for (int b = 1; b <= lbm.body_count(); ++b) {
    snap.forces.push_back(lbm.wall_force(b));
    snap.forces.push_back(lbm.wall_torque(b));
  }
  return snap;
}

/// The run at 1 and at 2 threads, checked bitwise equal; returns the 1-thread snapshot.
Snapshot run_and_compare(bool les_porous) {
  const int saved = omp_get_max_threads();
  const Snapshot one = run(1, 41, les_porous);
  const Snapshot two = run(2, 41, les_porous);
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

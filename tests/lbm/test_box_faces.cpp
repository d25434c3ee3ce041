// Box faces: periodic pairs, wall ghosts, and the input error for an unpaired periodic face.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "lbm/lbm_solver.hpp"

using namespace lbdem;
using namespace lbdem::lbm;

TEST_CASE("box faces: walls become bodies, a lone periodic face is an input error", "[lbm]") {
  LbmSettings s;
  s.nx = 5;
  s.ny = 4;
  s.nz = 3;
  s.faces[2].kind = s.faces[3].kind = FaceKind::wall;
  LbmSolver lbm(s);
  CHECK(lbm.grid().periodic(0));
  CHECK_FALSE(lbm.grid().periodic(1));
  CHECK(lbm.face_body(0) == 0);
  REQUIRE(lbm.face_body(2) == 1);
  REQUIRE(lbm.face_body(3) == 2);
  CHECK(lbm.body_name(2) == "y_hi");
  // The ghost rows behind y_lo and y_hi belong to their walls, interior cells are fluid.
  CHECK(lbm.flags().at(2, -1, 1) == 1);
  CHECK(lbm.flags().at(2, 4, 1) == 2);
  CHECK(lbm.flags().at(2, 3, 1) == kFluid);
  // Fluid at rest pushes each wall outwards with its pressure rho c_s^2 times the area nx nz.
  lbm.step();
  CHECK(lbm.wall_force(1).y() == Approx(-kCs2 * 5 * 3).epsilon(1e-14));
  CHECK(lbm.wall_force(2).y() == Approx(kCs2 * 5 * 3).epsilon(1e-14));

  s.faces[5].kind = FaceKind::wall;  // z_hi a wall, z_lo still periodic
  try {
    LbmSolver bad(s);
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    CHECK(e.key() == "faces.z_hi");
  }
}

// Walls other than the plane: restitution off a cylinder from inside and outside (same law as the
// plane, so e is reproduced), and a moving mesh piston: an elastic sphere at rest leaves a wall
// moving at V with 2V (infinite wall mass), and the work the wall did equals the energy it gave.
#include <catch2/catch.hpp>

#include "helpers/dem_setup.hpp"

using namespace lbdem;

TEST_CASE("restitution off a cylinder wall, inside and outside", "[dem][walls][physics]") {
  const double r = 5e-4, R = 5e-3, e = 0.6;
  for (bool inside : {true, false}) {
    auto s = test::settings(2e-7);
    dem::DemSolver sol(s, {test::glass(e, 0.0)});
    dem::Wall w;
    w.name = "cup";
    dem::CylinderWall c;
    c.radius = R;
    c.inside = inside;
    w.shape = c;
    sol.add_wall(w);
    // Moving radially (along x) towards the wall, starting just clear of it.
    const double x0 = inside ? R - r - 1e-6 : R + r + 1e-6;
    const double v = inside ? 0.5 : -0.5;
    sol.add_particle(Vec3(x0, 0, 0), Vec3(v, 0, 0), r, 0);
    test::run_through_contact(sol);
    INFO((inside ? "inside" : "outside"));
    // 1 %: as for the plane (t_c/50 here is finer than the restitution test's), the curvature of
    // the wall only changes R*, which e does not depend on.
    CHECK(-sol.particles().v[0].x() / v == Approx(e).epsilon(0.01));
  }
}

TEST_CASE("a moving mesh piston: rebound at 2V and wall work = energy given",
          "[dem][walls][mesh][physics]") {
  const double r = 5e-4, V = 0.2;
  auto s = test::settings(2e-7);
  dem::DemSolver sol(s, {test::glass(1.0, 0.0)});
  dem::Wall w;
  w.name = "piston";
  dem::MeshWall m;
  m.mesh = dem::TriangleMesh::from_triangles(
      {{Vec3(-0.005, -0.005, 0), Vec3(0.005, -0.005, 0), Vec3(0.005, 0.005, 0)},
       {Vec3(-0.005, -0.005, 0), Vec3(0.005, 0.005, 0), Vec3(-0.005, 0.005, 0)}});
  m.motion.velocity = Vec3(0, 0, V);
  w.shape = std::move(m);
  sol.add_wall(std::move(w));
  sol.add_particle(Vec3(0.001, 0.001, r + 2e-6), Vec3::Zero(), r, 0);
  test::run_through_contact(sol);
  const double m_p = sol.particles().mass[0];
  // Elastic Hertz contact with an infinitely heavy wall: exact 2V; 1e-3 covers the O(dt^{5/2})
  // energy error of one collision (test_energy.cpp) and the contact ending inside a step.
  CHECK(sol.particles().v[0].z() == Approx(2 * V).epsilon(1e-3));
  const auto en = sol.energy();
  CHECK(en.wall_work == Approx(0.5 * m_p * 4 * V * V).epsilon(1e-3));
  CHECK(std::abs(en.stored() - en.potential - en.wall_work) < 1e-3 * en.wall_work);
}

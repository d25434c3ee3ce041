// The analytic cuboid wall (impeller blades): closest-point geometry against hand-computed
// distances, the start-and-ramp motion against its closed form, and impacts on a face, an edge and
// a corner against the same cuboid given as a triangle mesh.
#include <catch2/catch.hpp>
#include <cmath>

#include "dem/walls/cuboid_mesh.hpp"
#include "helpers/dem_setup.hpp"

using namespace lbdem;

namespace {
// A 4 x 2 x 1 mm box rotated 30 degrees about z, centred at (1, 2, 3) mm.
dem::BoxWall tilted_box() {
  dem::BoxWall b;
  const double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
  b.center = Vec3(1e-3, 2e-3, 3e-3);
  b.axes = {Vec3(c, s, 0), Vec3(-s, c, 0), Vec3::UnitZ()};
  b.half = Vec3(2e-3, 1e-3, 0.5e-3);
  return b;
}
Vec3 body_point(const dem::BoxWall& b, double u, double v, double w) {
  return b.center + u * b.axes[0] + v * b.axes[1] + w * b.axes[2];
}
}  // namespace

TEST_CASE("Box wall: distance and normal to a face, an edge and a corner", "[dem][walls]") {
  const dem::BoxWall b = tilted_box();
  // Exact values by construction in the body frame; rounding of the 30-degree rotation is ~1e-19 m.
  const double tol = 1e-15;
  SECTION("face: 0.3 mm beyond the +u face") {
    const auto wp = dem::wall_point(b, body_point(b, 2.3e-3, 0.4e-3, -0.1e-3), 0);
    CHECK(wp.dist == Approx(0.3e-3).margin(tol));
    CHECK((wp.n + b.axes[0]).norm() < 1e-12);  // from the centre towards the wall
    CHECK((wp.point - body_point(b, 2e-3, 0.4e-3, -0.1e-3)).norm() < tol);
  }
  SECTION("edge: 0.3 mm beyond +u and 0.4 mm beyond -v") {
    const auto wp = dem::wall_point(b, body_point(b, 2.3e-3, -1.4e-3, 0.2e-3), 0);
    CHECK(wp.dist == Approx(0.5e-3).margin(tol));  // 3-4-5
    CHECK((wp.point - body_point(b, 2e-3, -1e-3, 0.2e-3)).norm() < tol);
  }
  SECTION("corner: (0.1, 0.2, 0.2) mm beyond three faces") {
    const auto wp = dem::wall_point(b, body_point(b, -2.1e-3, 1.2e-3, 0.7e-3), 0);
    CHECK(wp.dist == Approx(0.3e-3).margin(tol));  // sqrt(0.01 + 0.04 + 0.04) = 0.3
  }
  SECTION("centre inside: pushed out through the nearest face") {
    const auto wp = dem::wall_point(b, body_point(b, 0.5e-3, 0.1e-3, 0.45e-3), 0);
    CHECK(wp.dist == Approx(-0.05e-3).margin(tol));
    CHECK((wp.n + b.axes[2]).norm() < 1e-12);
  }
}

TEST_CASE("Prescribed motion: rest, linear ramp, then full speed", "[dem][walls]") {
  dem::BoxWall b = tilted_box();
  b.motion.axis_point = Vec3::Zero();
  b.motion.axis = Vec3::UnitZ();
  b.motion.omega = 20;  // [rad/s]
  b.motion.start = 0.1;
  b.motion.ramp = 0.2;
  // Angle: 0 before start, omega tau^2 / (2 ramp) during the ramp, omega (tau - ramp/2) after.
  const auto angle_at = [&](double t) {
    const Vec3 p0 = b.center, p = b.motion.position(p0, t);
    return std::atan2(p0.x() * p.y() - p0.y() * p.x(), p0.x() * p.x() + p0.y() * p.y());
  };
  CHECK(std::abs(angle_at(0.05)) < 1e-15);  // rounding of the cross product only
  CHECK(angle_at(0.2) == Approx(20 * 0.1 * 0.1 / 0.4).epsilon(1e-12));
  CHECK(angle_at(0.35) == Approx(20 * (0.25 - 0.1)).epsilon(1e-12));
  // Speed of a body point: omega r times the ramp fraction.
  const Vec3 p = b.motion.position(b.center, 0.2);
  CHECK(b.motion.velocity_at(p, 0.2).norm() ==
        Approx(20 * 0.5 * Vec3(p.x(), p.y(), 0).norm()).epsilon(1e-12));
  CHECK(b.motion.velocity_at(p, 0.05).norm() == 0);
}

namespace {
// A sphere thrown at the tilted box (analytic or meshed); returns its position and velocity after
// the bounce.
std::pair<Vec3, Vec3> bounce(bool mesh, const Vec3& start_body, const Vec3& dir_body) {
  const dem::BoxWall b = tilted_box();
  auto s = test::settings(5e-7);
  dem::DemSolver sol(s, {test::glass(0.7, 0.3)});
  dem::Wall w;
  w.name = "blade";
  if (mesh) {
    dem::MeshWall m;
    m.mesh = dem::cuboid_mesh(b.center, b.axes, b.half);
    w.shape = std::move(m);
  } else {
    w.shape = b;
  }
  sol.add_wall(std::move(w));
  const Vec3 dir = dir_body.x() * b.axes[0] + dir_body.y() * b.axes[1] + dir_body.z() * b.axes[2];
  sol.add_particle(body_point(b, start_body.x(), start_body.y(), start_body.z()),
                   0.3 * dir.normalized(), 2e-4, 0);
  test::run_through_contact(sol, 200000);
  for (int k = 0; k < 200; ++k) sol.step();
  return {sol.particles().x[0], sol.particles().v[0]};
}
}  // namespace

TEST_CASE("Box wall: impacts on a face, an edge and a corner match the meshed cuboid",
          "[dem][walls]") {
  // The mesh's closest point (triangle Voronoi regions, one contact per shared edge/vertex) and
  // the box's (clamping in the body frame) are the same point up to rounding, ~1e-19 m per step;
  // a single stable bounce does not amplify it, so 1e-12 m and 1e-9 m/s are generous.
  const Vec3 starts[] = {Vec3(0.5e-3, 1.4e-3, 0), Vec3(2.35e-3, 1.35e-3, 0.1e-3),
                         Vec3(2.3e-3, 1.3e-3, 0.8e-3)};
  const Vec3 dirs[] = {Vec3(0.2, -1, 0.1), Vec3(-1, -1, 0), Vec3(-1, -1, -1)};
  for (int c = 0; c < 3; ++c) {
    const auto a = bounce(false, starts[c], dirs[c]);
    const auto m = bounce(true, starts[c], dirs[c]);
    INFO("case " << c);
    CHECK((a.first - m.first).norm() < 1e-12);
    CHECK((a.second - m.second).norm() < 1e-9);
    const dem::BoxWall b = tilted_box();
    const Vec3 d = dirs[c].x() * b.axes[0] + dirs[c].y() * b.axes[1] + dirs[c].z() * b.axes[2];
    CHECK(a.second.dot(d) < -0.05 * d.norm());  // it did bounce back (e = 0.7 from 0.3 m/s)
  }
}

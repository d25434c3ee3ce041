// Solid cells from geometry: analytic cylinders and STL meshes voxelized onto the lattice, checked
// against analytic volumes and against each other, and the rigid-motion wall velocity.
//
// Volume tolerances. A cell is solid when its centre is inside, so the solid cubes differ from the
// body only in the shell of half-width h = sqrt(3)/2 dx (half a cell diagonal) about the surface:
// |N dx^3 - V| <= 2 h A = sqrt(3) A dx for a surface of area A (rigorous up to the curvature term,
// O(h^2) per unit area). The error is a sum over the ~ sqrt(3) A / dx^2 cells the surface cuts,
// each contributing (indicator - inside fraction) with zero mean and variance about 1/6 (for a
// fraction uniform in [0, 1]); on a surface that is not lattice-aligned the signs are close to
// independent, so the error is typically sqrt(sqrt(3) A / 6) cells, and 5 of these bound it.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "core/stl.hpp"
#include "helpers/meshes.hpp"
#include "dem/walls/triangle_mesh.hpp"
#include "lbm/geometry/cylinder.hpp"
#include "lbm/geometry/lattice_frame.hpp"
#include "lbm/geometry/mesh_voxelizer.hpp"
#include "lbm/geometry/rigid_motion.hpp"
#include "lbm/lbm_solver.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace lbdem;
using namespace lbdem::lbm;
using Catch::Matchers::Contains;
using lbdem::test::prism;

namespace {

LbmSettings box(int nx, int ny, int nz, bool walls) {
  LbmSettings s;
  s.nx = nx;
  s.ny = ny;
  s.nz = nz;
  if (walls)
    for (int f = 0; f < 6; ++f) s.faces[f].kind = FaceKind::wall;
  return s;
}

/// Cells of `body` among the markable cells (for_each_markable_cell).
Index count_body(const LbmSolver& lbm, int body) {
  Index n = 0;
  for_each_markable_cell(lbm.grid(),
                         [&](int x, int y, int z) { n += lbm.flags().at(x, y, z) == body; });
  return n;
}

/// The statistical volume tolerance of the header comment, in cells: 5 sqrt(sqrt(3) A / 6).
double staircase_tolerance(double area_cells) {
  return 5.0 * std::sqrt(std::sqrt(3.0) * area_cells / 6.0);
}

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("lbdem_geometry_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

/// Icosahedron subdivided `levels` times, corners on the sphere: a closed mesh whose rows pass
/// through edges and vertices at every orientation.
std::vector<Triangle> icosphere(const Vec3& centre, double r, int levels) {
  const double p = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> v = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                         {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& x : v) x.normalize();
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = mid.try_emplace(key, int(v.size()));
      if (fresh) v.push_back((v[a] + v[b]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> g;
    for (const auto& t : f) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      g.insert(g.end(), {{t[0], a, c}, {t[1], b, a}, {t[2], c, b}, {a, b, c}});
    }
    f = std::move(g);
  }
  std::vector<Triangle> out;
  for (const auto& t : f)
    out.push_back({centre + r * v[t[0]], centre + r * v[t[1]], centre + r * v[t[2]]});
  return out;
}

/// Volume and area of a closed triangle mesh (divergence theorem: sum of signed tetrahedra).
std::pair<double, double> volume_area(const std::vector<Triangle>& m) {
  double v = 0, a = 0;
  for (const Triangle& t : m) {
    v += t[0].dot(t[1].cross(t[2])) / 6;
    a += (t[1] - t[0]).cross(t[2] - t[0]).norm() / 2;
  }
  return {std::abs(v), a};
}

}  // namespace

TEST_CASE("voxelized cylinders have the analytic volume", "[lbm][geometry]") {
  SECTION("a tilted finite cylinder, solid inside") {
    LbmSolver lbm(box(64, 64, 64, false));
    const int body = lbm.add_body("rod");
    Cylinder c;
    c.axis_point = Vec3(31.3, 32.1, 30.7);
    c.axis = Vec3(1, 2, 3);
    c.radius = 10.3;
    c.start = -20.2;
    c.end = 19.9;
    const Index n = mark_cylinder(lbm, LatticeFrame::lattice_units(), c, SolidSide::inside, body);
    CHECK(n == count_body(lbm, body));
    const double len = c.end - c.start, r = c.radius;
    const double v = kPi * r * r * len, area = 2 * kPi * r * len + 2 * kPi * r * r;
    INFO("cells " << n << " volume " << v << " bound " << std::sqrt(3.0) * area << " statistical "
                  << staircase_tolerance(area));
    CHECK(std::abs(n - v) < staircase_tolerance(area));
  }
  SECTION("a chamber in a walled box (solid outside), in SI, ghosts included") {
    // Axis along z: every fluid layer is the same disc, so the layers' errors add coherently and
    // the check is per layer, with the 2-D form of the estimate (a curve of length P cuts about
    // sqrt(2) P cells): the Gauss circle problem, whose error grows slower than the perimeter.
    const int n_xy = 48, nz = 10;
    LbmSolver lbm(box(n_xy, n_xy, nz, true));
    const int body = lbm.add_body("cup");
    const LatticeFrame frame{Vec3(0.1, -0.2, 0.3), 2e-3};
    Cylinder c;
    c.axis_point = frame.to_si(Vec3(23.5 + 0.17, 23.5 - 0.23, 0));
    c.radius = 21.4 * frame.dx;
    // Caps half-way between layers: fluid in z = 0 .. nz - 2; the ghost layers and the top
    // layer lie beyond the caps.
    c.start = -0.5 * frame.dx;
    c.end = (nz - 1.5) * frame.dx;
    const Index n = mark_cylinder(lbm, frame, c, SolidSide::outside, body);
    CHECK(n == count_body(lbm, body));
    const double layer = double(n_xy + 2) * (n_xy + 2), r = 21.4;
    const double fluid_layer = (layer * (nz + 2) - double(n)) / (nz - 1);
    const double tol = 5.0 * std::sqrt(std::sqrt(2.0) * 2 * kPi * r / 6);
    INFO("fluid cells per layer " << fluid_layer << " area " << kPi * r * r << " tolerance "
                                  << tol);
    CHECK(std::abs(fluid_layer - kPi * r * r) < tol);
    CHECK(lbm.flags().at(0, 0, 2) == body);     // corner of the box
    CHECK(lbm.flags().at(-1, 24, 2) == body);   // ghost of the x_lo wall, outside the cup
    CHECK(lbm.flags().at(24, 24, -1) == body);  // ghost below the bottom cap
    CHECK(lbm.flags().at(24, 24, nz - 1) == body);
    CHECK(lbm.flags().at(24, 24, nz - 2) == kFluid);
    CHECK(lbm.flags().at(24, 24, 0) == kFluid);
  }
}

TEST_CASE("an axis-aligned cube on lattice coordinates gives its exact cell count",
          "[lbm][geometry]") {
  // Every face holds cell centres and every row through the faces' diagonals and edges meets them
  // exactly: the tie rules of mesh_voxelizer.hpp make each axis the half-open [lo, hi).
  const Vec3 lo(4, 5, 6), hi(20, 21, 22);
  std::vector<Triangle> cube;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      Vec3 c[4];
      for (int k = 0; k < 4; ++k) {
        Vec3 v = lo;
        v[axis] = side ? hi[axis] : lo[axis];
        v[(axis + 1) % 3] = (k == 1 || k == 2) ? hi[(axis + 1) % 3] : lo[(axis + 1) % 3];
        v[(axis + 2) % 3] = k >= 2 ? hi[(axis + 2) % 3] : lo[(axis + 2) % 3];
        c[k] = v;
      }
      cube.push_back({c[0], c[1], c[2]});
      cube.push_back({c[0], c[2], c[3]});
    }
  LbmSolver lbm(box(26, 26, 26, false));
  const int body = lbm.add_body("cube");
  const Index n =
      mark_mesh(lbm, LatticeFrame::lattice_units(), cube, SolidSide::inside, body, "cube");
  CHECK(n == 16 * 16 * 16);
  CHECK(lbm.flags().at(4, 5, 6) == body);
  CHECK(lbm.flags().at(19, 20, 21) == body);
  CHECK(lbm.flags().at(20, 10, 10) == kFluid);
}

TEST_CASE("STL sphere and rotated cube voxelize to their volume", "[lbm][geometry]") {
  const LatticeFrame frame{Vec3(-0.01, 0.02, 0.005), 0.5e-3};
  LbmSolver lbm(box(40, 40, 40, true));
  const int sphere = lbm.add_body("sphere");
  // A sphere of 15.3 cells as 1280 facets, through a binary STL file in mm.
  const std::vector<Triangle> mesh =
      icosphere(frame.to_si(Vec3(19.6, 19.2, 20.1)), 15.3 * frame.dx, 3);
  std::vector<Triangle> mm = mesh;
  for (Triangle& t : mm)
    for (Vec3& v : t) v *= 1e3;
  const std::string path = temp_path("sphere.stl");
  dem::TriangleMesh::from_triangles(mm).write_stl_binary(path);
  const Index n = mark_stl(lbm, frame, path, 1e-3, SolidSide::inside, sphere, "fluid.body.stl");
  std::filesystem::remove(path);
  CHECK(n == count_body(lbm, sphere));
  const auto [v_si, a_si] = volume_area(mesh);
  const double v = v_si / std::pow(frame.dx, 3), area = a_si / (frame.dx * frame.dx);
  INFO("cells " << n << " polyhedron volume " << v << " sphere "
                << 4.0 / 3 * kPi * std::pow(15.3, 3) << " tolerance " << staircase_tolerance(area));
  CHECK(std::abs(n - v) < staircase_tolerance(area));

  // A cube of side 17.3 cells turned about (1, 1, 1)/sqrt(3) then x: no face is aligned with
  // the lattice. Solid outside (a cubic chamber) marks the complement.
  LbmSolver box_lbm(box(40, 40, 40, false));
  const int wall = box_lbm.add_body("chamber");
  const double side = 17.3;
  const Eigen::Matrix3d rot =
      (Eigen::AngleAxisd(0.4, Vec3::UnitX()) * Eigen::AngleAxisd(0.7, Vec3(1, 1, 1).normalized()))
          .toRotationMatrix();
  std::vector<Triangle> cube;
  const Vec3 centre(19.7, 20.2, 19.9);
  for (int axis = 0; axis < 3; ++axis)
    for (int s = -1; s <= 1; s += 2) {
      const Vec3 n_f = s * Vec3::Unit(axis), e1 = Vec3::Unit((axis + 1) % 3),
                 e2 = Vec3::Unit((axis + 2) % 3);
      auto corner = [&](double a, double b) {
        return Vec3(centre + rot * (side / 2 * (n_f + a * e1 + b * e2)));
      };
      cube.push_back({corner(-1, -1), corner(1, -1), corner(1, 1)});
      cube.push_back({corner(-1, -1), corner(1, 1), corner(-1, 1)});
    }
  const Index outside =
      mark_mesh(box_lbm, LatticeFrame::lattice_units(), cube, SolidSide::outside, wall, "chamber");
  const double inside = 40.0 * 40 * 40 - outside, v_cube = std::pow(side, 3);
  INFO("cube cells " << inside << " volume " << v_cube << " tolerance "
                     << staircase_tolerance(6 * side * side));
  CHECK(std::abs(inside - v_cube) < staircase_tolerance(6 * side * side));
}

TEST_CASE("a closed STL cylinder gives the analytic cylinder's cells", "[lbm][geometry]") {
  // The prism is inscribed: it lies inside the circle by at most the sagitta r (1 - cos(pi / n)),
  // and float32 storage plus the 2^-12-cell rounding of the voxelizer move it by < 1e-3 cells.
  // Cells may differ only when their centre lies within that band of the analytic surface.
  const int sides = 256;
  const double r = 11.6, eta = 1e-3, sagitta = r * (1 - std::cos(kPi / sides));
  // Dyadic dx and origin: lattice coordinates of dyadic SI points are exact.
  const LatticeFrame frame{Vec3(0.25, -0.5, 0.125), 1.0 / 1024};
  struct Case {
    const char* name;
    Vec3 point;  // lattice coordinates
    Vec3 axis;
  };
  // Axis along x through integer (y, z): rows meet the cap fans at their centre and along their
  // spokes, and graze the side facets edge-on. Then a tilted axis.
  for (const Case& k :
       {Case{"along x", Vec3(20.3, 16, 17), Vec3::UnitX()},
        Case{"tilted", Vec3(19.8, 16.4, 17.2), Vec3(0.3, -0.5, 0.8).normalized()}}) {
    INFO(k.name);
    const double t0 = -8.37, t1 = 9.61;
    Cylinder c;
    c.axis_point = frame.to_si(k.point);
    c.axis = k.axis;
    c.radius = r * frame.dx;
    c.start = t0 * frame.dx;
    c.end = t1 * frame.dx;
    LbmSolver analytic(box(40, 34, 34, true)), meshed(box(40, 34, 34, true));
    const int a = analytic.add_body("cylinder"), m = meshed.add_body("cylinder");
    const Index na = mark_cylinder(analytic, frame, c, SolidSide::inside, a);
    const std::string path = temp_path("cylinder.stl");
    dem::TriangleMesh::from_triangles(prism(c.axis_point, k.axis, c.radius, c.start, c.end, sides))
        .write_stl_binary(path);
    const Index nm = mark_stl(meshed, frame, path, 1.0, SolidSide::inside, m, "impeller.stl");
    std::filesystem::remove(path);
    int differ = 0, unexplained = 0;
    for_each_markable_cell(analytic.grid(), [&](int x, int y, int z) {
      if ((analytic.flags().at(x, y, z) == a) == (meshed.flags().at(x, y, z) == m)) return;
      ++differ;
      const Vec3 d = Vec3(x, y, z) - k.point;
      const double t = d.dot(k.axis), rho = (d - t * k.axis).norm();
      const bool lateral = rho > r - sagitta - eta && rho < r + eta;
      const bool cap = std::abs(t - t0) < eta || std::abs(t - t1) < eta;
      if (!lateral && !cap) ++unexplained;
    });
    INFO("analytic " << na << " mesh " << nm << " differing " << differ);
    CHECK(unexplained == 0);
    CHECK(differ <= 10);  // the band holds ~ 2 pi r L (sagitta + eta) ~ 2.4 cell centres
  }
}

TEST_CASE("an open mesh is an input error naming the key", "[lbm][geometry]") {
  std::vector<Triangle> mesh = icosphere(Vec3(12.2, 11.7, 12.4), 8.3, 2);
  // Drop the facet facing +x: rows through its hole cross the rest once.
  std::size_t facing = 0;
  for (std::size_t t = 0; t < mesh.size(); ++t)
    if ((mesh[t][0] + mesh[t][1] + mesh[t][2]).x() >
        (mesh[facing][0] + mesh[facing][1] + mesh[facing][2]).x())
      facing = t;
  mesh.erase(mesh.begin() + std::ptrdiff_t(facing));
  LbmSolver lbm(box(24, 24, 24, false));
  const int body = lbm.add_body("bob");
  REQUIRE_THROWS_AS(mark_mesh(lbm, LatticeFrame::lattice_units(), mesh, SolidSide::inside, body,
                              "rheometer.bob_stl"),
                    InputError);
  CHECK_THROWS_WITH(mark_mesh(lbm, LatticeFrame::lattice_units(), mesh, SolidSide::inside, body,
                              "rheometer.bob_stl"),
                    Contains("rheometer.bob_stl") && Contains("not closed"));
}

TEST_CASE("rigid-motion wall velocity", "[lbm][geometry]") {
  // u = U + omega n x (x - x0): at x0 + e_x about z, the rotation gives omega e_y.
  const WallVelocity u = rigid_motion(Vec3(1, 2, 3), Vec3(0, 0, 2), 0.01, Vec3(0.001, 0, 0));
  CHECK((u(Vec3(2, 2, 7)) - Vec3(0.001, 0.01, 0)).norm() < 1e-15);
  CHECK((u(Vec3(1, 2, -4)) - Vec3(0.001, 0, 0)).norm() < 1e-15);
  CHECK_THROWS_AS(rigid_motion(Vec3::Zero(), Vec3::Zero(), 0.01), std::invalid_argument);
}

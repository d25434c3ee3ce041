// Triangle-mesh walls: closest point per Voronoi region, STL input/output, and the choice of
// distinct contacts (one on a flat mesh anywhere, two in a concave corner, one on a convex ridge).
#include "dem/walls/triangle_mesh.hpp"

#include "core/error.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

using lbdem::InputError;
using lbdem::Vec3;
using namespace lbdem::dem;
using Tri = std::array<Vec3, 3>;
using Catch::Matchers::Contains;

namespace {

std::string temp_path(const std::string& name) {  // per process: ctest runs cases side by side
  return (std::filesystem::temp_directory_path() /
          ("lbdem_mesh_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// nx x ny squares of side s in the plane z = 0, each split along its (i,j)-(i+1,j+1) diagonal,
/// counter-clockwise seen from +z; `to_3d` maps (u, v, 0) to the wanted placement.
template <class Map>
std::vector<Tri> grid(int nx, int ny, double s, Map to_3d) {
  std::vector<Tri> t;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const Vec3 p00 = to_3d(Vec3(i * s, j * s, 0)), p10 = to_3d(Vec3((i + 1) * s, j * s, 0)),
                 p11 = to_3d(Vec3((i + 1) * s, (j + 1) * s, 0)),
                 p01 = to_3d(Vec3(i * s, (j + 1) * s, 0));
      t.push_back({p00, p10, p11});
      t.push_back({p00, p11, p01});
    }
  return t;
}
std::vector<Tri> flat_grid(int nx, int ny) {
  return grid(nx, ny, 1.0, [](const Vec3& v) { return v; });
}

std::vector<Tri> unit_cube() {  // outward normals
  std::vector<Tri> t;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      auto corner = [&](int a, int b) {
        Vec3 v = Vec3::Zero();
        v[axis] = side, v[u] = a, v[w] = b;
        return v;
      };
      // (u, w) is right-handed about +axis, so this order faces +axis; swap it for side 0.
      Tri t1 = {corner(0, 0), corner(1, 0), corner(1, 1)},
          t2 = {corner(0, 0), corner(1, 1), corner(0, 1)};
      if (side == 0) std::swap(t1[1], t1[2]), std::swap(t2[1], t2[2]);
      t.push_back(t1), t.push_back(t2);
    }
  return t;
}

std::vector<MeshHit> hits_of(const TriangleMesh& m, const Vec3& p, double range) {
  std::vector<MeshHit> h;
  for (int t = 0; t < static_cast<int>(m.size()); ++t) {
    const auto& v = m.triangles[t];
    const MeshClosest c = closest_point_on_triangle(p, m.vertices[v[0]], m.vertices[v[1]],
                                                    m.vertices[v[2]], t, m.tri_edges[t], v);
    if (c.dist2 < range * range) h.push_back({t, c});
  }
  return h;
}

std::vector<MeshClosest> contacts(const TriangleMesh& m, const Vec3& p, double range) {
  const std::vector<MeshHit> h = hits_of(m, p, range);
  std::vector<char> keep;
  select_mesh_contacts(m, h, keep);
  std::vector<MeshClosest> out;
  for (std::size_t k = 0; k < h.size(); ++k)
    if (keep[k]) out.push_back(h[k].closest);
  return out;
}

}  // namespace

TEST_CASE("closest point in each Voronoi region of a triangle", "[dem][mesh]") {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  const std::array<int, 3> edge_ids = {10, 11, 12}, vertex_ids = {20, 21, 22};
  struct Case {
    Vec3 p, point;
    double dist2;
    MeshFeature feature;
    int id;
  };
  // Hand-computed: projections onto the plane z = 0, the edges and the corners.
  const Case cases[] = {
      {{0.5, 0.5, 1}, {0.5, 0.5, 0}, 1.0, MeshFeature::Face, 7},
      {{-1, -1, 0.5}, {0, 0, 0}, 2.25, MeshFeature::Vertex, 20},
      {{3, -1, 0}, {2, 0, 0}, 2.0, MeshFeature::Vertex, 21},
      {{-1, 3, 2}, {0, 2, 0}, 6.0, MeshFeature::Vertex, 22},
      {{1, -1, 1}, {1, 0, 0}, 2.0, MeshFeature::Edge, 10},     // edge ab
      {{2, 1, 1}, {1.5, 0.5, 0}, 1.5, MeshFeature::Edge, 11},  // edge bc: t = 1/4 from b
      {{-2, 1, 0}, {0, 1, 0}, 4.0, MeshFeature::Edge, 12},     // edge ca
      // 1e-17 inside and outside edge ab: both classified on the edge (kSnap), same point.
      {{1, 1e-17, 1}, {1, 0, 0}, 1.0, MeshFeature::Edge, 10},
      {{1, -1e-17, 1}, {1, 0, 0}, 1.0, MeshFeature::Edge, 10},
  };
  for (const Case& k : cases) {
    const MeshClosest r = closest_point_on_triangle(k.p, a, b, c, 7, edge_ids, vertex_ids);
    INFO("p = " << k.p.transpose());
    CHECK(r.feature == k.feature);
    CHECK(r.feature_id == k.id);
    // Inputs are exact binary fractions: only a few roundings separate the result from the value.
    CHECK((r.point - k.point).norm() < 1e-15);
    CHECK(r.dist2 == Approx(k.dist2).epsilon(1e-14));
  }
}

TEST_CASE("closest point is the projection onto the triangle (random triangles)", "[dem][mesh]") {
  // Reference: x is the Euclidean projection of p onto the convex triangle iff
  // (p - x) . (y - x) <= 0 for every y in it, i.e. for its three corners; and no point of a dense
  // barycentric sample is nearer.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vec3 p = 2 * Vec3(u(rng), u(rng), u(rng));
    const MeshClosest r = closest_point_on_triangle(p, a, b, c, 0, {0, 1, 2}, {0, 1, 2});
    // Products of O(1) lengths: 1e-12 is far above their rounding (1e-15) and far below a miss.
    for (const Vec3* y : {&a, &b, &c}) CHECK((p - r.point).dot(*y - r.point) <= 1e-12);
    CHECK(r.dist2 == Approx((p - r.point).squaredNorm()).epsilon(1e-14));
    const std::array<Vec3, 3> v = {a, b, c};
    if (r.feature == MeshFeature::Vertex) CHECK((r.point - v[r.feature_id]).norm() < 1e-14);
    if (r.feature == MeshFeature::Edge) {  // on the line of edge k = (v_k, v_k+1); O(1) lengths
      const Vec3 e0 = v[r.feature_id], e = v[(r.feature_id + 1) % 3] - e0;
      CHECK((r.point - e0).cross(e).norm() < 1e-12);
    }
    double best = 1e300;
    for (int i = 0; i <= 100; ++i)
      for (int j = 0; i + j <= 100; ++j)
        best =
            std::min(best, (p - (a + (b - a) * (i / 100.0) + (c - a) * (j / 100.0))).squaredNorm());
    CHECK(r.dist2 <= best * (1 + 1e-14));  // a sample can tie the exact minimum, never beat it
  }
}

TEST_CASE("mesh topology: merged vertices and shared edges", "[dem][mesh]") {
  const TriangleMesh sq = TriangleMesh::from_triangles(flat_grid(1, 1));
  CHECK(sq.vertices.size() == 4);
  CHECK(sq.edges.size() == 5);
  const TriangleMesh cube = TriangleMesh::from_triangles(unit_cube());
  CHECK(cube.vertices.size() == 8);
  CHECK(cube.edges.size() == 18);
  // Closed, consistently oriented surface: each edge in exactly two triangles, opposite ways.
  std::vector<int> uses(cube.edges.size(), 0), forward(cube.edges.size(), 0);
  for (std::size_t t = 0; t < cube.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int e = cube.tri_edges[t][k];
      ++uses[e];
      forward[e] += cube.triangles[t][k] == cube.edges[e][0];
    }
  CHECK(std::all_of(uses.begin(), uses.end(), [](int n) { return n == 2; }));
  CHECK(std::all_of(forward.begin(), forward.end(), [](int n) { return n == 1; }));
  CHECK(cube.bbox_min() == Vec3::Zero());
  CHECK(cube.bbox_max() == Vec3::Ones());
  // Merge tolerance: 1e-13 apart merges at the default 1e-12 m, 1e-9 apart does not.
  std::vector<Tri> t = flat_grid(1, 1);
  t[1][0].x() += 1e-13;
  CHECK(TriangleMesh::from_triangles(t).vertices.size() == 4);
  t[1][0].x() += 1e-9;
  CHECK(TriangleMesh::from_triangles(t).vertices.size() == 5);
}

TEST_CASE("binary STL write and read round trip", "[dem][mesh]") {
  const TriangleMesh cube = TriangleMesh::from_triangles(unit_cube());
  const std::string path = temp_path("cube.stl");
  cube.write_stl_binary(path);
  CHECK(std::filesystem::file_size(path) == 84 + 50 * 12);
  const TriangleMesh back = TriangleMesh::from_stl(path, 1.0, "walls.file");
  CHECK(back.vertices.size() == 8);
  CHECK(back.edges.size() == 18);
  REQUIRE(back.size() == 12);
  for (std::size_t t = 0; t < 12; ++t)  // 0 and 1 are exact in float: bitwise round trip
    for (int k = 0; k < 3; ++k)
      CHECK(back.vertices[back.triangles[t][k]] == cube.vertices[cube.triangles[t][k]]);
  CHECK(TriangleMesh::from_stl(path, 1e-3, "walls.file").bbox_max() == Vec3::Constant(1e-3));

  const std::string sq_path = temp_path("square.stl");
  TriangleMesh::from_triangles(flat_grid(1, 1)).write_stl_binary(sq_path);
  const TriangleMesh sq = TriangleMesh::from_stl(sq_path, 1.0, "walls.file");
  CHECK(sq.vertices.size() == 4);
  CHECK(sq.edges.size() == 5);

  SECTION("a binary file whose header begins with \"solid\"") {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.write("solid cube exported by a CAD tool", 33);
    f.close();
    const TriangleMesh m = TriangleMesh::from_stl(path, 1.0, "walls.file");
    CHECK(m.size() == 12);
    CHECK(m.vertices.size() == 8);
  }
  std::filesystem::remove(path);
  std::filesystem::remove(sq_path);
}

TEST_CASE("ASCII STL read", "[dem][mesh]") {
  const std::string facets =
      "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
      "      vertex 1 1 0\n    endloop\n  endfacet\r\n"
      "  FACET NORMAL 0.0e0 0 0\r\n OUTER LOOP\r\n VERTEX 0 0 0\r\n VERTEX 1.0e0 1 0\r\n"
      " VERTEX +0 1 0\r\n ENDLOOP\r\n ENDFACET\r\n";
  const std::size_t split = facets.find("FACET");
  const std::string path = temp_path("ascii.stl");
  // Bare "solid"; a name made of keywords; two solids in one file.
  for (const std::string& text : {"solid\n" + facets + "endsolid\n",
                                  "solid endsolid facet vertex\n" + facets + "endsolid x y",
                                  "solid a\n" + facets.substr(0, split) + "endsolid a\nsolid b\n" +
                                      facets.substr(split) + "endsolid b\n"}) {
    write_text(path, text);
    const TriangleMesh m = TriangleMesh::from_stl(path, 2.0, "walls.file");
    CHECK(m.size() == 2);
    CHECK(m.vertices.size() == 4);
    CHECK(m.edges.size() == 5);
    CHECK(m.bbox_max() == Vec3(2, 2, 0));
  }
  write_text(path, "solid\n" + facets.substr(0, split + 60));  // cut inside the second facet
  CHECK_THROWS_AS(TriangleMesh::from_stl(path, 1.0, "walls.file"), InputError);
  std::string typo = "solid\n" + facets;
  typo.replace(typo.find("ENDLOOP"), 7, "ENDLOOOP");  // on line 14
  write_text(path, typo);
  CHECK_THROWS_WITH(TriangleMesh::from_stl(path, 1.0, "walls.file"),
                    Contains(path) && Contains("line 14") && Contains("walls.file"));
  std::filesystem::remove(path);
}

TEST_CASE("STL and mesh input errors", "[dem][mesh]") {
  const std::string missing = temp_path("no_such_file.stl");
  REQUIRE_THROWS_AS(TriangleMesh::from_stl(missing, 1.0, "walls.file"), InputError);
  CHECK_THROWS_WITH(TriangleMesh::from_stl(missing, 1.0, "walls.file"),
                    Contains(missing) && Contains("walls.file"));
  std::vector<Tri> t = flat_grid(2, 1);
  t[2][2] = 0.5 * (t[2][0] + t[2][1]);  // collinear corners
  REQUIRE_THROWS_AS(TriangleMesh::from_triangles(t), InputError);
  CHECK_THROWS_WITH(TriangleMesh::from_triangles(t), Contains("triangle 2"));
  REQUIRE_THROWS_AS(TriangleMesh::from_triangles({}), InputError);

  const std::string path = temp_path("bad.stl");
  TriangleMesh m = TriangleMesh::from_triangles(flat_grid(2, 1));
  m.vertices.push_back(m.vertices[m.triangles[3][1]]);  // file facet 3 collapses, alone
  m.triangles[3][0] = static_cast<int>(m.vertices.size()) - 1;
  m.write_stl_binary(path);
  REQUIRE_THROWS_AS(TriangleMesh::from_stl(path, 1.0, "walls.file"), InputError);
  CHECK_THROWS_WITH(TriangleMesh::from_stl(path, 1.0, "walls.file"),
                    Contains(path) && Contains("triangle 3"));
  std::filesystem::resize_file(path, 84 + 50 * 4 - 1);  // binary size no longer 84 + 50 n
  CHECK_THROWS_WITH(TriangleMesh::from_stl(path, 1.0, "walls.file"), Contains(path));
  CHECK_THROWS_AS(TriangleMesh::from_stl(path, 0.0, "walls.file"), InputError);
  std::filesystem::remove(path);
}

namespace {
/// A sphere on a flat mesh must feel the plane: one contact, at distance from the mesh footprint.
void check_one_flat_contact(const TriangleMesh& m, const Vec3& p, double range, double expected) {
  INFO("centre " << p.transpose());
  std::vector<MeshHit> h = hits_of(m, p, range);
  std::vector<char> keep;
  select_mesh_contacts(m, h, keep);
  REQUIRE(std::count(keep.begin(), keep.end(), 1) == 1);
  const MeshClosest c = h[std::find(keep.begin(), keep.end(), 1) - keep.begin()].closest;
  // Coordinates O(1) and distances >= 0.1: rounding is ~1e-15 relative, 1e-12 leaves margin.
  CHECK(std::sqrt(c.dist2) == Approx(expected).epsilon(1e-12));
  std::reverse(h.begin(), h.end());  // same contact whatever the order of the hits
  select_mesh_contacts(m, h, keep);
  REQUIRE(std::count(keep.begin(), keep.end(), 1) == 1);
  const MeshClosest& c2 = h[std::find(keep.begin(), keep.end(), 1) - keep.begin()].closest;
  CHECK((c2.feature == c.feature && c2.feature_id == c.feature_id));
}
}  // namespace

TEST_CASE("one contact anywhere on a flat mesh", "[dem][mesh]") {
  const TriangleMesh m = TriangleMesh::from_triangles(flat_grid(2, 2));  // 8 coplanar triangles
  REQUIRE(m.size() == 8);
  const double h = 0.2, r = 0.3;
  for (const Vec3& xy : {Vec3(0.7, 0.2, 0),    // face interior
                         Vec3(0.97, 0.5, 0),   // near the shared edge x = 1
                         Vec3(0.55, 0.5, 0),   // near a diagonal
                         Vec3(1.0, 0.4, 0),    // exactly over the shared edge x = 1
                         Vec3(0.5, 0.5, 0),    // exactly over a diagonal
                         Vec3(1.0, 1.0, 0),    // exactly over the central vertex (6 triangles)
                         Vec3(0.5, 0.03, 0),   // near a boundary edge
                         Vec3(2.0, 1.0, 0),    // exactly over a boundary vertex
                         Vec3(1.1, 1.05, 0)})  // near a vertex: disc reaches its other triangles
    check_one_flat_contact(m, xy + Vec3(0, 0, h), r, h);
  // Classification: over a shared edge both triangles report that edge, at the same point; over
  // the central vertex all 6 triangles holding it report it.
  for (const auto& [xy, feature, count] : {std::tuple(Vec3(1.0, 0.4, 0), MeshFeature::Edge, 2),
                                           std::tuple(Vec3(0.5, 0.5, 0), MeshFeature::Edge, 2),
                                           std::tuple(Vec3(1.0, 1.0, 0), MeshFeature::Vertex, 6)}) {
    const auto hits = hits_of(m, xy + Vec3(0, 0, h), r);
    REQUIRE(static_cast<int>(hits.size()) >= count);
    int same = 0;
    for (const MeshHit& k : hits)
      same += k.closest.feature == feature && k.closest.point == xy &&
              k.closest.feature_id == hits[0].closest.feature_id;
    CHECK(same == count);
  }
  // Contact discs (radius sqrt(0.9^2 - 0.5^2) = 0.75, and 0.22 at (1.1, 1.05) above) reach
  // triangles that share no edge with the one under the centre; their nearest points lie on their
  // own edges (not on an edge of that one) and must still be dropped.
  check_one_flat_contact(m, Vec3(1.3, 1.2, 0.5), 0.9, 0.5);
  check_one_flat_contact(m, Vec3(0.6, 0.45, 0.5), 0.9, 0.5);

  // Sweep, outside the footprint too (the nearest point is then on the boundary), on exact
  // quarter-lines of the grid and between them, at several heights.
  for (int i = 0; i <= 88; ++i)
    for (int j = 0; j <= 88; ++j) {
      const double x = (i - 4) / 40.0, y = (j - 4) / 40.0, z = 0.1 + 0.05 * ((i + j) % 5);
      const double dx = std::max({0.0, -x, x - 2}), dy = std::max({0.0, -y, y - 2});
      check_one_flat_contact(m, Vec3(x, y, z), 0.45, std::sqrt(dx * dx + dy * dy + z * z));
    }
}

TEST_CASE("one contact on a tilted and offset flat mesh", "[dem][mesh]") {
  // Generic placement so "over an edge" is exact only to rounding.
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(3.7, -1.2, 0.4);
  const auto place = [&](const Vec3& v) -> Vec3 { return rot * v + shift; };
  const TriangleMesh m = TriangleMesh::from_triangles(grid(3, 3, 0.5, place));
  const Vec3 n = rot.col(2);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.05, 1.45), hd(0.1, 0.3);
  for (int k = 0; k < 2000; ++k) {
    // Every third centre exactly over a grid vertex, edge midpoint or diagonal midpoint.
    Vec3 uv(u(rng), u(rng), 0);
    if (k % 3 == 0) uv = (uv * 4).array().round().matrix() / 4;
    const double h = hd(rng);
    check_one_flat_contact(m, place(uv) + h * n, 0.35, h);
    const bool inside = uv.head<2>().minCoeff() > 0 && uv.head<2>().maxCoeff() < 1.5;
    if (k % 3 == 0 && inside && std::fmod(uv.x() + uv.y(), 0.5) != 0) {  // over an inner edge
      // Both triangles of the edge must agree on it, bit for bit, despite the rounding.
      const auto hits = hits_of(m, place(uv) + h * n, 0.35);
      std::vector<MeshClosest> on;
      for (const MeshHit& q : hits)
        if (q.closest.dist2 < h * h * (1 + 1e-9)) on.push_back(q.closest);
      INFO("uv = " << uv.transpose());
      REQUIRE(on.size() == 2);
      CHECK(on[0].feature == MeshFeature::Edge);
      CHECK((on[1].feature == on[0].feature && on[1].feature_id == on[0].feature_id));
      CHECK(on[1].point == on[0].point);
    }
  }
}

TEST_CASE("two contacts in a concave corner and one on a convex ridge", "[dem][mesh]") {
  // Floor z = 0 and wall y = 0 (outward +y), x, y, z in [0, 2], as one mesh sharing the corner.
  std::vector<Tri> t = flat_grid(2, 2);
  for (Tri w : grid(2, 2, 1.0, [](const Vec3& v) { return Vec3(v.x(), 0, v.y()); }))
    t.push_back({w[0], w[2], w[1]});
  const TriangleMesh corner = TriangleMesh::from_triangles(t);
  REQUIRE(corner.vertices.size() == 9 + 6);  // the corner line's 3 vertices are shared
  for (const Vec3& p : {Vec3(0.7, 0.2, 0.25), Vec3(1.0, 0.2, 0.25), Vec3(0.7, 0.2, 0.2)}) {
    INFO("centre " << p.transpose());
    const auto c = contacts(corner, p, 0.3);
    REQUIRE(c.size() == 2);
    std::vector<double> d = {std::sqrt(c[0].dist2), std::sqrt(c[1].dist2)};
    std::sort(d.begin(), d.end());
    std::vector<double> want = {p.y(), p.z()};  // distances to wall and floor
    std::sort(want.begin(), want.end());
    CHECK(d[0] == Approx(want[0]).epsilon(1e-12));  // O(1) coordinates: rounding ~1e-15
    CHECK(d[1] == Approx(want[1]).epsilon(1e-12));
  }

  // Roof: slopes from y = -1, z = 0 and y = 1, z = 0 up to the ridge y = 0, z = 1, x in [0, 2].
  std::vector<Tri> roof;
  for (int i = 0; i < 2; ++i) {
    const Vec3 l0(i, -1, 0), l1(i + 1, -1, 0), r0(i, 0, 1), r1(i + 1, 0, 1), s0(i, 1, 0),
        s1(i + 1, 1, 0);
    roof.push_back({l0, l1, r1}), roof.push_back({l0, r1, r0});
    roof.push_back({r0, r1, s1}), roof.push_back({r0, s1, s0});
  }
  const TriangleMesh ridge = TriangleMesh::from_triangles(roof);
  const double want = std::hypot(0.05, 0.2);  // centre 0.05 aside, 0.2 above the ridge line
  for (const auto& [x, feature] :
       {std::pair(0.5, MeshFeature::Edge), std::pair(1.0, MeshFeature::Vertex)}) {
    const auto c = contacts(ridge, Vec3(x, 0.05, 1.2), 0.3);
    REQUIRE(c.size() == 1);
    CHECK(c[0].feature == feature);
    CHECK(c[0].point.isApprox(Vec3(x, 0, 1), 1e-14));
    CHECK(std::sqrt(c[0].dist2) == Approx(want).epsilon(1e-12));
  }

  // Closed cube seen from outside: one face, one edge or one corner contact.
  const TriangleMesh cube = TriangleMesh::from_triangles(unit_cube());
  const std::pair<Vec3, MeshFeature> around[] = {{{0.5, 0.4, 1.2}, MeshFeature::Face},
                                                 {{0.5, 1.1, 1.1}, MeshFeature::Edge},
                                                 {{1.1, 1.1, 1.1}, MeshFeature::Vertex}};
  for (const auto& [p, feature] : around) {
    const auto c = contacts(cube, p, 0.3);
    REQUIRE(c.size() == 1);
    CHECK(c[0].feature == feature);
  }
}

TEST_CASE("one point reported as vertex and as edge point is one contact", "[dem][mesh]") {
  // Rounding at the kSnap threshold can make one triangle report vertex V and another, holding V,
  // report its own edge through V at a distance larger by an ulp; both are the same point.
  const TriangleMesh m = TriangleMesh::from_triangles(flat_grid(2, 2));
  // Triangle 1 = ((0,0), (1,1), (0,1)) reports vertex (1,1); triangle 2 = ((0,1), (1,1), (1,2))
  // holds it too and reports its edge (1,1)-(1,2), which triangle 1 does not hold.
  const int t1 = 1, t2 = 2, v = m.triangles[1][1], e2 = m.tri_edges[2][1];
  REQUIRE(m.vertices[v] == Vec3(1, 1, 0));
  REQUIRE(m.edges[e2] == std::array<int, 2>{v, m.triangles[2][2]});
  const std::vector<MeshHit> hits = {
      {t2, {Vec3(1, 1, 0), 0.04 * (1 + 4e-16), MeshFeature::Edge, e2}},
      {t1, {Vec3(1, 1, 0), 0.04, MeshFeature::Vertex, v}}};
  std::vector<char> keep;
  select_mesh_contacts(m, hits, keep);
  CHECK(keep == std::vector<char>{0, 1});
}

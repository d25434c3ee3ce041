#include "dem/walls/triangle_mesh.hpp"

#include "core/error.hpp"
#include "core/stl.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace lbdem::dem {
namespace {

using Tri = std::array<Vec3, 3>;

// A triangle is degenerate when |(b-a) x (c-a)| <= 1e-12 L_max^2: the height is then below 1e-12 of
// its longest side, which is rounding noise for coordinates up to 1e4 L from the origin.
constexpr double kDegenerateRel = 1e-12;
// Barycentric / edge-parameter threshold below which a closest point is taken to lie on the edge /
// vertex; 1e4 times double rounding, so both triangles of a shared edge agree (see header).
constexpr double kSnap = 1e-12;
// Two squared distances within rounding of the points' size (1e-12, 1e4 times double epsilon) are
// treated as one contact point in select_mesh_contacts.
constexpr double kTieRel = 1e-12;

struct CellHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
    // Teschner et al. (2003) spatial hash primes; unsigned so the wrap-around is defined.
    return static_cast<std::size_t>(static_cast<std::uint64_t>(c[0]) * 73856093u ^
                                    static_cast<std::uint64_t>(c[1]) * 19349663u ^
                                    static_cast<std::uint64_t>(c[2]) * 83492791u);
  }
};

/// Builds the mesh; `key` and `value` (the STL path, or empty) go into every InputError.
TriangleMesh build(const std::vector<Tri>& tris, double merge_tol, const std::string& key,
                   const std::string& value) {
  if (tris.empty())
    throw InputError(key, value, "the mesh holds no triangles", "give a surface with facets");
  if (!(merge_tol >= 0) || !std::isfinite(merge_tol))
    throw InputError(key, to_text(merge_tol), "vertex merge tolerance must be finite and >= 0", "");
  double extent = 0;
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (const Vec3& v : tris[t]) {
      if (!v.allFinite())
        throw InputError(key, value,
                         "triangle " + std::to_string(t) + " has a non-finite coordinate",
                         "repair the geometry file");
      extent = std::max(extent, v.cwiseAbs().maxCoeff());
    }
  // Grid cells of at least 2 merge_tol, so a vertex looks in at most 2 cells per axis; the 1e-12
  // extent floor keeps cell indices far inside int64.
  const double h = std::max({2 * merge_tol, 1e-12 * extent, std::numeric_limits<double>::min()});
  std::unordered_map<std::array<std::int64_t, 3>, int, CellHash> cell_head;
  std::vector<int> next_in_cell;
  TriangleMesh m;
  auto vertex_id = [&](const Vec3& v) {
    std::array<std::int64_t, 3> lo, hi;
    for (int d = 0; d < 3; ++d) {
      lo[d] = static_cast<std::int64_t>(std::floor((v[d] - merge_tol) / h));
      hi[d] = static_cast<std::int64_t>(std::floor((v[d] + merge_tol) / h));
    }
    int best = -1;  // lowest matching id, so the result does not depend on hash order
    for (auto i = lo[0]; i <= hi[0]; ++i)
      for (auto j = lo[1]; j <= hi[1]; ++j)
        for (auto k = lo[2]; k <= hi[2]; ++k) {
          const auto it = cell_head.find({i, j, k});
          for (int u = it == cell_head.end() ? -1 : it->second; u >= 0; u = next_in_cell[u])
            if ((m.vertices[u] - v).cwiseAbs().maxCoeff() <= merge_tol && (best < 0 || u < best))
              best = u;
        }
    if (best >= 0) return best;
    const int id = static_cast<int>(m.vertices.size());
    m.vertices.push_back(v);
    std::array<std::int64_t, 3> cell;
    for (int d = 0; d < 3; ++d) cell[d] = static_cast<std::int64_t>(std::floor(v[d] / h));
    const auto [it, fresh] = cell_head.try_emplace(cell, id);
    next_in_cell.push_back(fresh ? -1 : it->second);
    it->second = id;
    return id;
  };
  std::unordered_map<std::uint64_t, int> edge_of;
  m.triangles.reserve(tris.size());
  m.tri_edges.reserve(tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const std::array<int, 3> v = {vertex_id(tris[t][0]), vertex_id(tris[t][1]),
                                  vertex_id(tris[t][2])};
    const Vec3 &a = m.vertices[v[0]], &b = m.vertices[v[1]], &c = m.vertices[v[2]];
    const double l2 =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0] ||
        (b - a).cross(c - a).norm() <= kDegenerateRel * l2)
      throw InputError(key, value, "triangle " + std::to_string(t) + " (0-based) has zero area",
                       "remove the degenerate facet (e.g. repair the STL) or check the scale");
    std::array<int, 3> e;
    for (int k = 0; k < 3; ++k) {
      const int p = std::min(v[k], v[(k + 1) % 3]), q = std::max(v[k], v[(k + 1) % 3]);
      const std::uint64_t ekey =
          (static_cast<std::uint64_t>(p) << 32) | static_cast<std::uint32_t>(q);
      const auto [it, fresh] = edge_of.try_emplace(ekey, static_cast<int>(m.edges.size()));
      if (fresh) m.edges.push_back({p, q});
      e[k] = it->second;
    }
    m.triangles.push_back(v);
    m.tri_edges.push_back(e);
  }
  return m;
}

void put_le32(std::string& s, std::size_t at, std::uint32_t u) {
  for (int i = 0; i < 4; ++i) s[at + i] = static_cast<char>((u >> (8 * i)) & 0xffu);
}

}  // namespace

TriangleMesh TriangleMesh::from_triangles(const std::vector<std::array<Vec3, 3>>& tris,
                                          double merge_tol) {
  return build(tris, merge_tol, "triangle_mesh", "");
}

TriangleMesh TriangleMesh::from_stl(const std::string& path, double scale, const std::string& key) {
  const std::vector<Tri> tris = read_stl(path, scale, key);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Tri& tri : tris)
    for (const Vec3& v : tri) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  // Coordinates of one vertex repeated per facet agree to float rounding at worst; 1e-9 of the
  // diagonal is below any real feature yet far above that noise near zero (e.g. 1e-17 vs 0).
  const double diag = tris.empty() ? 0.0 : (hi - lo).norm();
  return build(tris, std::isfinite(diag) ? 1e-9 * diag : 0.0, key, path);
}

void TriangleMesh::write_stl_binary(const std::string& path) const {
  std::string buf(84 + 50 * triangles.size(), '\0');
  // The header must not begin with "solid" (readers would try ASCII first).
  const std::string_view header = "binary STL written by lbdem";
  std::copy(header.begin(), header.end(), buf.begin());
  put_le32(buf, 80, static_cast<std::uint32_t>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec3 &a = vertices[triangles[t][0]], &b = vertices[triangles[t][1]],
               &c = vertices[triangles[t][2]];
    const Vec3 n = (b - a).cross(c - a).normalized();
    const std::array<Vec3, 4> rows = {n, a, b, c};
    for (int r = 0; r < 4; ++r)
      for (int d = 0; d < 3; ++d)
        put_le32(buf, 84 + 50 * t + 12 * r + 4 * d,
                 std::bit_cast<std::uint32_t>(static_cast<float>(rows[r][d])));
  }
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(buf.data(), static_cast<std::streamsize>(buf.size()));
  f.close();
  if (!f) throw std::runtime_error("cannot write STL file " + path);
}

Vec3 TriangleMesh::bbox_min() const {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());  // empty box: +inf
  for (const Vec3& v : vertices) lo = lo.cwiseMin(v);
  return lo;
}

Vec3 TriangleMesh::bbox_max() const {
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  for (const Vec3& v : vertices) hi = hi.cwiseMax(v);
  return hi;
}

MeshClosest closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                      int tri_id, const std::array<int, 3>& edge_ids,
                                      const std::array<int, 3>& vertex_ids) {
  const std::array<const Vec3*, 3> v = {&a, &b, &c};
  auto at_vertex = [&](int k) {
    return MeshClosest{*v[k], (p - *v[k]).squaredNorm(), MeshFeature::Vertex, vertex_ids[k]};
  };
  // Projection onto edge k, measured from its endpoint with the lower global id so that both
  // triangles sharing the edge compute the same point bit for bit.
  auto on_edge = [&](int k) {
    int i = k, j = (k + 1) % 3;
    if (vertex_ids[j] < vertex_ids[i]) std::swap(i, j);
    const Vec3 e = *v[j] - *v[i];
    const double t = std::clamp((p - *v[i]).dot(e) / e.squaredNorm(), 0.0, 1.0);
    if (t <= kSnap) return at_vertex(i);
    if (t >= 1 - kSnap) return at_vertex(j);
    const Vec3 x = *v[i] + t * e;
    return MeshClosest{x, (p - x).squaredNorm(), MeshFeature::Edge, edge_ids[k]};
  };
  // Ericson (2005) sec. 5.1.5, ClosestPtPointTriangle; edges: 0 = ab, 1 = bc, 2 = ca.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return at_vertex(0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return at_vertex(1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return on_edge(0);
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return at_vertex(2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return on_edge(2);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return on_edge(1);
  const double denom = va + vb + vc;  // = |ab x ac|^2 > 0: barycentrics are va, vb, vc / denom
  const std::array<bool, 3> thin = {va <= kSnap * denom, vb <= kSnap * denom, vc <= kSnap * denom};
  const int n_thin = thin[0] + thin[1] + thin[2];
  if (n_thin >= 2) return at_vertex(!thin[0] ? 0 : !thin[1] ? 1 : 2);
  if (n_thin == 1) return on_edge(thin[0] ? 1 : thin[1] ? 2 : 0);  // edge opposite the thin vertex
  const Vec3 x = a + ab * (vb / denom) + ac * (vc / denom);
  return MeshClosest{x, (p - x).squaredNorm(), MeshFeature::Face, tri_id};
}

void select_mesh_contacts(const TriangleMesh& mesh, const std::vector<MeshHit>& hits,
                          std::vector<char>& keep) {
  const std::size_t n = hits.size();
  keep.assign(n, 0);
  auto same = [&](std::size_t i, std::size_t j) {
    return hits[i].closest.feature == hits[j].closest.feature &&
           hits[i].closest.feature_id == hits[j].closest.feature_id;
  };
  auto holds = [&](int tri, const MeshClosest& c) {
    const auto& ids = c.feature == MeshFeature::Edge ? mesh.tri_edges[tri] : mesh.triangles[tri];
    return c.feature == MeshFeature::Face
               ? tri == c.feature_id
               : std::find(ids.begin(), ids.end(), c.feature_id) != ids.end();
  };
  // Hits on one feature are one contact: its distance is the least of theirs, and it is carried
  // by the hit with the lowest triangle id (then position). Contacts are visited nearest first.
  // Scratch kept per thread: this runs once per sphere and mesh in every step.
  thread_local std::vector<double> d2;
  thread_local std::vector<std::size_t> reps;
  d2.resize(n);
  reps.clear();
  for (std::size_t i = 0; i < n; ++i) {
    d2[i] = hits[i].closest.dist2;
    bool rep = true;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && same(i, j)) {
        d2[i] = std::min(d2[i], hits[j].closest.dist2);
        rep = rep && std::pair(hits[i].tri, i) < std::pair(hits[j].tri, j);
      }
    if (rep) reps.push_back(i);
  }
  auto before = [&](std::size_t i, std::size_t j) {
    return std::tuple(d2[i], hits[i].closest.feature, hits[i].closest.feature_id) <
           std::tuple(d2[j], hits[j].closest.feature, hits[j].closest.feature_id);
  };
  std::sort(reps.begin(), reps.end(), before);
  for (std::size_t r = 0; r < reps.size(); ++r) {
    const std::size_t i = reps[r];
    const MeshClosest& ci = hits[i].closest;
    bool drop = false;
    // Another triangle holding this edge/vertex is nearest elsewhere: no local minimum here.
    for (std::size_t m = 0; m < n && ci.feature != MeshFeature::Face && !drop; ++m)
      drop = !same(m, i) && holds(hits[m].tri, ci) &&
             (hits[m].closest.feature == MeshFeature::Face || before(m, i));
    // A kept nearer edge/vertex of one of this contact's triangles at the same distance (within
    // rounding) is the same point, classified differently at the kSnap threshold.
    for (std::size_t s = 0; s < r && ci.feature != MeshFeature::Face && !drop; ++s) {
      const std::size_t j = reps[s];
      const MeshClosest& cj = hits[j].closest;
      if (!keep[j] || cj.feature == MeshFeature::Face) continue;
      const double d = std::sqrt(std::max(d2[i], d2[j]));
      const double delta =
          kTieRel * (std::max(ci.point.cwiseAbs().maxCoeff(), cj.point.cwiseAbs().maxCoeff()) + d);
      if (std::abs(d2[i] - d2[j]) > 2 * d * delta + delta * delta) continue;
      for (std::size_t m = 0; m < n && !drop; ++m) drop = same(m, i) && holds(hits[m].tri, cj);
    }
    keep[i] = !drop;
  }
}

}  // namespace lbdem::dem

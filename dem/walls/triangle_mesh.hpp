#pragma once
// Triangle-mesh walls (STL geometry): topology, closest-point queries and the choice of distinct
// contacts of one sphere with one mesh.
#include "core/types.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lbdem::dem {

enum class MeshFeature : std::uint8_t { Face = 0, Edge = 1, Vertex = 2 };

struct MeshClosest {    // closest point of a triangle to a point p
  Vec3 point;           // closest point on the triangle [m]
  double dist2;         // squared distance |p - point|^2 [m^2]
  MeshFeature feature;  // where the closest point lies: triangle interior, an edge, a vertex
  int feature_id;       // Face: triangle id; Edge: global edge id; Vertex: global vertex id
};

/// Triangle surface with shared-vertex/edge topology (needed so a sphere touching a shared edge or
/// vertex gets one contact, not two).
struct TriangleMesh {
  std::vector<Vec3> vertices;  // unique vertices [m], reference configuration
  // Vertex ids, counter-clockwise seen from the outward side.
  std::vector<std::array<int, 3>> triangles;
  // Global edge id of edge k = (v_k, v_{(k+1)%3}) of each triangle.
  std::vector<std::array<int, 3>> tri_edges;
  std::vector<std::array<int, 2>> edges;  // vertex ids of each global edge (lower id first)

  /// Builds topology; merges vertices whose coordinates are each equal within `merge_tol` [m]
  /// (STL files repeat coordinates per facet). Vertex and edge ids follow first appearance.
  /// Throws InputError on degenerate (zero-area) triangles naming the triangle index, on
  /// non-finite coordinates, or if there are no triangles.
  static TriangleMesh from_triangles(const std::vector<std::array<Vec3, 3>>& tris,
                                     double merge_tol = 1e-12);
  /// Reads binary or ASCII STL through lbdem::read_stl (core/stl.hpp: format detection, `scale`
  /// multiplies coordinates, 1e-3 for a file in mm). Vertices are merged within 1e-9 of
  /// the bounding-box diagonal: far below any real feature, far above noise such as 1e-17 vs 0. The
  /// vertex order of each facet defines the outward side (right-hand rule); the stored normal is
  /// ignored, since many exporters write zeros there. `key` is the config key named in the
  /// InputError when the file is missing, unreadable or malformed.
  static TriangleMesh from_stl(const std::string& path, double scale, const std::string& key);
  /// Writes binary STL (float32, as the format demands); throws std::runtime_error if it cannot.
  void write_stl_binary(const std::string& path) const;

  std::size_t size() const { return triangles.size(); }
  Vec3 bbox_min() const;  // +inf for an empty mesh
  Vec3 bbox_max() const;  // -inf for an empty mesh
};

/// Closest point on triangle (a, b, c) to p, with the feature classified: Voronoi-region method of
/// Ericson, Real-Time Collision Detection (2005), sec. 5.1.5. A closest point whose barycentric
/// coordinate is below 1e-12 is moved onto that edge (and an edge point within 1e-12 of the edge
/// length onto the vertex), so that both triangles sharing an edge classify a point over it alike.
/// Edge k of the triangle is (v_k, v_{(k+1)%3}) with v = (a, b, c); ids are passed in so the result
/// carries global ids.
MeshClosest closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                      int tri_id, const std::array<int, 3>& edge_ids,
                                      const std::array<int, 3>& vertex_ids);

/// One candidate contact of a sphere with triangle `tri` of a mesh.
struct MeshHit {
  int tri;
  MeshClosest closest;
};

/// Chooses which of one sphere's hits on ONE mesh (all with dist2 below the contact range squared)
/// are real, distinct contacts: the local minima of the distance from the sphere centre over the
/// whole surface. The distance from the centre is convex on each triangle, so an Edge/Vertex hit
/// is a local minimum only if no other triangle holding that edge/vertex has its closest point
/// elsewhere (nearer). Hence:
///  - every Face hit is kept;
///  - hits on the same edge or vertex are one contact, carried by the lowest triangle id;
///  - an Edge/Vertex hit is dropped if another triangle holding that edge/vertex reports a Face,
///    or a different edge/vertex that is nearer (ties: Edge before Vertex, then lower id);
///  - an Edge/Vertex hit within rounding (1e-12 relative) of the distance of an already kept
///    edge/vertex of its own triangle is the same point, and is dropped.
/// A sphere on a flat mesh then gets exactly one contact anywhere (the same trajectory as on an
/// analytic plane), even when the contact disc covers triangles that share no edge with the one
/// below the centre; a sphere in a concave corner keeps both faces; a sphere on a convex ridge
/// gets one edge contact. Writes keep[k] (0 or 1) for hits[k]; the result depends only on the
/// hits (and on their order only through exact duplicates).
void select_mesh_contacts(const TriangleMesh& mesh, const std::vector<MeshHit>& hits,
                          std::vector<char>& keep);

}  // namespace lbdem::dem

#pragma once
// A cuboid as a closed triangle mesh (12 triangles, outward winding): the meshed twin of BoxWall,
// for impeller blades given as meshes and for tests that hold the two against each other.
#include <array>

#include "dem/walls/triangle_mesh.hpp"

namespace lbdem::dem {

/// Cuboid with the given centre, orthonormal right-handed axes and half extents [m].
TriangleMesh cuboid_mesh(const Vec3& center, const std::array<Vec3, 3>& axes, const Vec3& half);

}  // namespace lbdem::dem

#pragma once
// STL geometry input (binary and ASCII), shared by the DEM mesh walls and the LBM voxelizer: both
// start from the same triangle soup, so a wall and the fluid's solid cells come from one reader.
#include "core/types.hpp"

#include <array>
#include <string>
#include <vector>

namespace lbdem {

/// One facet: three corners, counter-clockwise seen from the outward side (right-hand rule).
using Triangle = std::array<Vec3, 3>;

/// Reads a binary or ASCII STL file into a triangle soup (corners repeated per facet, in file
/// order), each coordinate multiplied by `scale` (1e-3 for a file in mm). A file is ASCII if it
/// starts with "solid" and parses as ASCII ("solid ... facet normal n n n outer loop vertex x y z
/// (x3) endloop endfacet ... endsolid", several solids allowed); a binary file may also start with
/// "solid", so otherwise its size must be the binary 84 + 50 n. The stored normal is ignored, since
/// many exporters write zeros there. Throws InputError naming `key` and the path when the scale is
/// not positive and finite, or the file is missing, unreadable or malformed (an ASCII error names
/// the line).
std::vector<Triangle> read_stl(const std::string& path, double scale, const std::string& key);

}  // namespace lbdem

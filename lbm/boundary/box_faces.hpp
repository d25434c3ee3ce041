#pragma once
// The six faces of the box: each periodic, or a body made of the ghost layer behind it: a half-way
// bounce-back wall (optionally moving tangentially, or at rest with a slip fraction: partial or
// free slip, slip_wall.hpp), a velocity inlet (bounce-back with Ladd's term at the inflow
// velocity, bounce_back.hpp) or a density outlet (anti-bounce-back, open_boundary.hpp).
#include "core/error.hpp"
#include "core/types.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/grid.hpp"

#include <array>
#include <string>
#include <string_view>

namespace lbdem::lbm {

enum class FaceKind { periodic, wall, inlet, outlet };

struct FaceBoundary {
  FaceKind kind = FaceKind::periodic;
  Vec3 wall_velocity = Vec3::Zero();  // wall: its velocity; inlet: the inflow velocity [lattice]
  double density = 1.0;               // outlet: rho_out, pressure rho_out c_s^2 [lattice units]
  // wall at rest: slip fraction s in [0, 1] [-], the share of specular reflection in the wall's
  // populations (slip_wall.hpp): 0 no slip (half-way bounce-back, unchanged), 1 free slip. The
  // solver refuses s > 0 on a moving wall, an inlet, an outlet or a periodic face.
  double slip = 0.0;
  // outlet: whether gas may enter through it; false bounces back the links of a cell with inflow
  // for that step (open_boundary.hpp: a vortex crossing the outlet then cannot feed itself).
  bool backflow = true;
};

/// Faces in the order x_lo, x_hi, y_lo, y_hi, z_lo, z_hi (face = 2 axis + side).
struct BoxFaces {
  static constexpr std::array<std::string_view, 6> kNames = {"x_lo", "x_hi", "y_lo",
                                                             "y_hi", "z_lo", "z_hi"};
  std::array<FaceBoundary, 6> face{};

  static BoxFaces all_periodic() { return {}; }
  FaceBoundary& operator[](int f) { return face[std::size_t(f)]; }
  const FaceBoundary& operator[](int f) const { return face[std::size_t(f)]; }

  /// Which axes wrap; a periodic face must have a periodic opposite face.
  std::array<bool, 3> periodic_axes() const {
    std::array<bool, 3> p{};
    for (int a = 0; a < 3; ++a) {
      const bool lo = face[2 * a].kind == FaceKind::periodic;
      const bool hi = face[2 * a + 1].kind == FaceKind::periodic;
      if (lo != hi)
        throw InputError(std::string("faces.") + std::string(kNames[2 * a + (lo ? 1 : 0)]), "",
                         "the opposite face is periodic, so this one must be too",
                         "make both " + std::string(kNames[2 * a]) + " and " +
                             std::string(kNames[2 * a + 1]) + " periodic, or neither");
      p[std::size_t(a)] = lo;
    }
    return p;
  }
};

/// Marks the ghost layer behind each wall face with flag body_of_face[f] (0: leave periodic
/// ghosts alone). Later faces overwrite earlier ones on shared edges and corners, so an edge ghost
/// belongs to the z face, then the y face.
inline void mark_box_faces(FlagField& flags, const std::array<CellFlag, 6>& body_of_face) {
  const Grid& g = flags.grid();
  for (int f = 0; f < 6; ++f) {
    if (body_of_face[std::size_t(f)] == kFluid) continue;
    const int axis = f / 2;
    const int layer = f % 2 ? g.extent(axis) : -1;
    int lo[3] = {-1, -1, -1}, hi[3] = {g.nx(), g.ny(), g.nz()};
    lo[axis] = hi[axis] = layer;
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) flags.set(x, y, z, body_of_face[std::size_t(f)]);
  }
}

}  // namespace lbdem::lbm

#pragma once
// A wall of any shape, with the loads it received in the last step.
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

#include "dem/walls/box_wall.hpp"
#include "dem/walls/cylinder_wall.hpp"
#include "dem/walls/mesh_wall.hpp"
#include "dem/walls/plane_wall.hpp"
#include "dem/walls/tube_wall.hpp"

namespace lbdem::dem {

struct Wall {
  std::string name;
  int material = 0;
  std::variant<PlaneWall, CylinderWall, MeshWall, BoxWall, TubeWall> shape;
  Vec3 torque_origin = Vec3::Zero();  // torques are reported about this point [m]
  // Loads on the wall from the particles in the last step (deterministic sums).
  Vec3 force = Vec3::Zero();   // [N]
  Vec3 torque = Vec3::Zero();  // [N m]
};

/// Where an analytic wall (plane, cylinder, box or tube) is seen from x at time t. Mesh walls have
/// per-triangle contacts (MeshWall::closest) and must not be passed here.
inline WallPoint analytic_wall_point(const Wall& w, const Vec3& x, double t) {
  return std::visit(
      [&](const auto& shape) -> WallPoint {
        if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, MeshWall>) {
          return {Vec3::UnitX(), std::numeric_limits<double>::infinity(), x, Vec3::Zero()};
        } else {
          return wall_point(shape, x, t);
        }
      },
      w.shape);
}

/// One particle-wall interaction candidate (built at neighbour rebuilds, sorted by particle).
struct WallContactList {
  std::vector<std::uint32_t> particle;
  std::vector<std::uint16_t> wall;
  std::vector<std::int32_t> tri;  // triangle of a mesh wall, -1 for analytic walls
  std::vector<ContactHistory> history;
  std::vector<ContactTally> tally;
  std::vector<ContactRecord> record;
  std::vector<std::uint8_t> state;
  std::vector<Vec3> force;        // on the particle [N]
  std::vector<Vec3> wall_torque;  // on the wall about its torque_origin [N m]
  std::vector<Vec3> contact_point;
  std::vector<double> power;         // F_on_particle . v_wall [W]
  std::vector<std::uint32_t> first;  // entries of particle p: [first[p], first[p+1])

  std::size_t size() const { return particle.size(); }
  void resize(std::size_t n) {
    particle.resize(n), wall.resize(n), tri.resize(n);
    history.assign(n, ContactHistory{});
    tally.assign(n, ContactTally{});
    record.assign(n, ContactRecord{});
    state.assign(n, 0);
    force.assign(n, Vec3::Zero());
    wall_torque.assign(n, Vec3::Zero());
    contact_point.assign(n, Vec3::Zero());
    power.assign(n, 0.0);
  }
};

}  // namespace lbdem::dem

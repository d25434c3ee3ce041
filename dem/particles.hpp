#pragma once
// Structure-of-arrays particle storage: one array per property, a 3-vector per particle
// as one contiguous Eigen::Vector3d. Spheres only.
#include "core/types.hpp"

#include <cstdint>
#include <vector>

namespace lbdem::dem {

struct ParticleArrays {
  std::vector<Vec3> x;          // position [m]
  std::vector<Vec3> v;          // velocity [m/s]
  std::vector<Vec3> omega;      // angular velocity [rad/s]
  std::vector<Vec3> force;      // total force of the last evaluation [N]
  std::vector<Vec3> torque;     // total torque of the last evaluation [N m]
  std::vector<Vec3> external;   // force from another phase (gas drag, -V grad p) [N], set by the
                                // coupling between steps and held over each step; 0 otherwise
  std::vector<double> radius;   // [m]
  std::vector<double> mass;     // [kg]
  std::vector<double> inertia;  // moment of inertia 2/5 m R^2 [kg m^2]
  std::vector<std::int32_t> material;
  std::vector<std::int64_t> id;  // unique, stable across sorting, removal and restart

  std::size_t size() const { return x.size(); }

  void add(const Vec3& pos, const Vec3& vel, const Vec3& w, double r, double density, int mat,
           std::int64_t pid) {
    const double m = density * 4.0 / 3.0 * kPi * r * r * r;
    x.push_back(pos);
    v.push_back(vel);
    omega.push_back(w);
    force.push_back(Vec3::Zero());
    torque.push_back(Vec3::Zero());
    external.push_back(Vec3::Zero());
    radius.push_back(r);
    mass.push_back(m);
    inertia.push_back(0.4 * m * r * r);
    material.push_back(mat);
    id.push_back(pid);
  }

  /// Reorders every array so that new[k] = old[order[k]]; `order` may drop entries (removal).
  template <class IndexVec>
  void permute(const IndexVec& order) {
    apply(x, order), apply(v, order), apply(omega, order), apply(force, order);
    apply(torque, order), apply(external, order), apply(radius, order), apply(mass, order),
        apply(inertia, order);
    apply(material, order), apply(id, order);
  }

 private:
  template <class T, class IndexVec>
  static void apply(std::vector<T>& a, const IndexVec& order) {
    std::vector<T> b(order.size());
    // A gather per array, on all threads: a rebuild every few steps sorts every array.
#pragma omp parallel for schedule(static) if (order.size() >= 4096)
    for (std::size_t k = 0; k < order.size(); ++k) b[k] = a[order[k]];
    a.swap(b);
  }
};

}  // namespace lbdem::dem

#pragma once
// The DEM engine: velocity-Verlet integration of spheres with the composed contact law, a Verlet
// neighbour list over linked cells, walls, collision statistics and energy accounting.
//
// Time step (docs/physics.md, DEM integration; docs/architecture.md, The time loop):
//  1. half kick and drift: v += dt/2 F/m, omega += dt/2 T/I, x += dt v; walls move to t + dt;
//  2. neighbour rebuild if a particle moved more than skin/2 (or a wall and a particle together
//  more
//     than the skin): periodic wrap, removals, spatial sort, new pair and wall lists, history
//     carried;
//  3. pair pass, in parallel over pairs, each writing only its own force slot, with the velocity
//     predicted to the end of the step (v + dt/2 F_old/m: second-order consistent, which the
//     dashpot needs to reproduce e; the half-step velocity alone misses e = 0.3 by more than 1 %);
//  4. particle pass, in parallel over particles: wall contacts, then the gather of pair forces in a
//     fixed order (as i, then as j), gravity, and the second half kick;
//  5. serial event scan (contact starts and ends) and fixed-block sums of wall loads.
// The result is bitwise independent of the number of OpenMP threads.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "dem/collision_stats.hpp"
#include "dem/contact/registry.hpp"
#include "dem/domain.hpp"
#include "dem/material.hpp"
#include "dem/pair_list.hpp"
#include "dem/particles.hpp"
#include "dem/walls/wall.hpp"

namespace lbdem {
class H5Out;
class H5In;
}  // namespace lbdem

namespace lbdem::dem {

/// Force and torque on each particle from the pairs where it is i, summed by the pair pass.
struct RowSums {
  std::vector<Vec3> f, t;
};

struct DemSettings {
  double dt = 1e-6;                  // [s]
  Vec3 gravity = Vec3(0, 0, -9.81);  // [m/s^2]
  double skin = 1e-4;                // Verlet skin [m]
  Domain domain;
  ContactSettings contact;
  CollisionSettings collisions;
  int sort_every = 1;      // spatial sort every n-th rebuild
  double lost_margin = 0;  // particles this far outside a non-periodic face are removed [m]
};

/// Energy accounts [J]. Stored: kinetic, potential (relative to the reference of the first call),
/// elastic. Dissipated by mechanism. Sources: work of moving walls and of external forces,
/// spring energy entered by stiffness change, energy of particles added and removed.
struct EnergyTotals {
  double kinetic_translational = 0, kinetic_rotational = 0, potential = 0, elastic = 0;
  double normal_damping = 0, tangential_damping = 0, sliding = 0, rolling = 0;
  double stiffness_change = 0, wall_work = 0, inserted = 0, removed = 0;
  double external_work = 0;  // of ParticleArrays::external (the gas: drag, -V grad p)

  double kinetic() const { return kinetic_translational + kinetic_rotational; }
  double stored() const { return kinetic() + potential + elastic; }
  double dissipated() const { return normal_damping + tangential_damping + sliding + rolling; }
  /// Energy put in since the start: initial stored energy + every source.
  double injected(double stored0) const {
    return stored0 + wall_work + external_work + stiffness_change + inserted - removed;
  }
};

/// The first particle found unsound during a step (DemSolver::alarm): its state after that step's
/// half kick and drift, when the check runs.
struct DemAlarm {
  std::int64_t step = 0;  // the step that found it
  double time = 0;        // [s] at the end of that step
  std::int64_t id = 0;    // ParticleArrays::id
  Vec3 x, v, omega, force, torque;
  bool finite = true;  // false: a non-finite component; true: faster than the speed limit
};

class DemSolver {
 public:
  DemSolver(const DemSettings& s, std::vector<Material> materials);

  ParticleArrays& particles() { return p_; }
  const ParticleArrays& particles() const { return p_; }
  const std::vector<Material>& materials() const { return materials_; }
  const DemSettings& settings() const { return s_; }

  /// Adds a particle; takes effect at the next step (forces a neighbour rebuild).
  void add_particle(const Vec3& x, const Vec3& v, double radius, int material);
  /// Marks particles for removal at the next rebuild (an outlet); their energy is booked as
  /// removed.
  void remove_particles(const std::vector<std::uint32_t>& indices);
  int add_wall(Wall w);
  std::vector<Wall>& walls() { return walls_; }
  const std::vector<Wall>& walls() const { return walls_; }

  /// One step. The watchdog folded into its first pass (half kick and drift) checks every particle:
  /// a non-finite position, velocity, angular velocity, force or torque, or a speed above
  /// set_speed_limit() raises alarm() for the first such particle (lowest index: the same for any
  /// thread count) and ends the step there, before the neighbour search meets the bad state.
  void step();
  /// The speed above which a particle raises the alarm [m/s]; infinite (only non-finite states)
  /// unless set.
  void set_speed_limit(double v_max) { speed_limit2_ = v_max * v_max; }
  const std::optional<DemAlarm>& alarm() const { return alarm_; }
  /// Books the work of ParticleArrays::external in energy() from now on (the coupling calls it;
  /// it costs one sum over the particles per step).
  void track_external_work() { track_external_ = true; }
  double time() const { return t_; }
  std::int64_t steps() const { return step_; }
  std::int64_t rebuilds() const { return rebuilds_; }
  std::int64_t lost() const { return lost_; }
  std::int64_t next_id() const { return next_id_; }
  double mass_removed() const { return mass_removed_; }

  EnergyTotals energy() const;
  std::size_t contacts_pp() const;  // pairs touching now
  std::size_t contacts_pw() const;
  /// Each particle's coordination number: the particles it touches now (pairs with overlap at the
  /// last evaluation; walls not counted).
  std::vector<std::int32_t> coordination() const;
  const CollisionStats& collisions() const { return stats_; }
  CollisionStats& collisions() { return stats_; }
  double interaction_range() const;  // largest distance beyond touch at which the law acts [m]

  /// Version of the checkpoint layout; load() refuses any other (bump when the saved structs
  /// change).
  static constexpr int kCheckpointLayout = 5;
  void save(H5Out& out) const;
  void load(const H5In& in);

 private:
  void check_loaded() const;
  void rebuild();
  void build_wall_list(const CellList& cells, double extra);
  void update_walls();
  template <class Table>
  void pair_pass(const Table& t);
  template <class Table>
  void particle_pass(const Table& t);
  void event_scan();
  void book_energy();
  void sum_wall_loads();
  double wall_displacement() const;

  DemSettings s_;
  std::vector<Material> materials_;
  AnyLawTable law_;
  ParticleArrays p_;
  std::vector<Wall> walls_;
  PairList pairs_;
  // The last rebuild's old list, kept as storage for the next (dem_rebuild.cpp): one more list
  // resident between rebuilds, about 230 B per pair (settled bed: 2,231 instead of 1,688 B per
  // particle at N = 100,352), against page faults on fresh arrays at every rebuild (default jet
  // mill: neighbour search 5.5 s instead of 7.3-7.7 s).
  PairList spare_pairs_;
  // The cells of the last rebuild, kept for their buffers: the sparse set `slot` is the one array
  // of the grid's size, allocated once (dem_rebuild.cpp; a rebuild costs O(particles)).
  CellList cells_;
  WallContactList wc_;
  CollisionStats stats_;
  std::vector<Vec3> x_ref_;            // positions at the last rebuild
  std::vector<Vec3> v_pred_, w_pred_;  // end-of-step predicted velocities
  RowSums row_sums_;
  std::vector<EnergyRates> pair_rates_, wall_rates_;  // the step's energy rates per block
  std::vector<double> wall_partials_;  // block partials of the wall loads (reused) // i-side pair
                                       // sums of the step
  std::vector<std::vector<Vec3>>
      wall_ref_;  // moving mesh vertices, box corners at the last rebuild
  std::vector<std::uint8_t> remove_flag_;
  double t_ = 0;
  std::int64_t step_ = 0, rebuilds_ = 0, lost_ = 0, next_id_ = 0;
  bool need_rebuild_ = true;
  double max_radius_ = 0;
  // Energy sources and sinks: the contacts' spring energy entered by stiffness change, and the
  // work of walls and of insertion and removal; the dashpots' total powers of the last step
  // (book_energy: their trapezoidal rule; the dissipated energies are kept in stats_).
  double stiffness_energy_ = 0, wall_work_ = 0, wall_power_prev_ = 0, inserted_ = 0, removed_ = 0;
  double p_normal_damping_prev_ = 0, p_tangential_damping_prev_ = 0;
  double mass_removed_ = 0;
  bool track_external_ = false;
  double speed_limit2_ = std::numeric_limits<double>::infinity();
  std::optional<DemAlarm> alarm_;
  double external_work_ = 0, external_power_prev_ = 0;
};

}  // namespace lbdem::dem

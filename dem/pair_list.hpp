#pragma once
// Half neighbour list of particle pairs (i < j) within the cut-off plus skin, sorted by (i, j),
// with each pair's contact history and accounting, and the two CSR views the deterministic gather
// needs: pairs where p is i (a contiguous range) and pairs where p is j (a transposed index).
#include <cstdint>
#include <vector>

#include "dem/contact/geometry.hpp"
#include "dem/csr_build.hpp"
#include "dem/domain.hpp"

namespace lbdem::dem {

/// What one contact keeps of its energy: what it has dissipated since it began [J] (damping by
/// the trapezoidal rule over its powers, plus sliding and rolling losses: the per-collision grid
/// and rows report it), its damping power at the last evaluation [W] (that rule's last term) and
/// the energy stored in it now [J]. The budget by mechanism is not kept per contact: the passes
/// sum each step's powers and losses per block of rows (EnergyRates), and DemSolver integrates
/// the totals (24 B per contact instead of the 64 of eight accounts).
struct ContactTally {
  double e_dissipated = 0;  // [J]
  double p_damping = 0;     // normal + tangential dashpot power at the last evaluation [W]
  double u_elastic = 0;     // springs + cohesion [J]
};

/// One step's energy rates summed over a block of contacts, by mechanism: the dashpots' powers at
/// this time level [W] and the energy the step moved by sliding, rolling and stiffness change [J].
struct EnergyRates {
  double p_normal_damping = 0, p_tangential_damping = 0;
  double e_sliding = 0, e_rolling = 0, e_stiffness = 0;
};

/// Impact record of the contact a pair is in now, for the statistics and the opt-in rows: written
/// at first touch (and each touching step while rows are on: the extremes), read at the start and
/// the end of the touch.
struct ContactRecord {
  double t_start = 0;      // [s]
  double vn_impact = 0;    // normal approach speed at first touch [m/s]
  double vt_impact = 0;    // tangential speed at first touch [m/s]
  double max_overlap = 0;  // [m] (tracked only when per-contact rows are on)
  double max_force = 0;    // largest normal contact force [N] (likewise)
};

/// State bits of a pair or wall contact after an evaluation. kStarted/kEnded mark the step in which
/// a touch began or ended; the serial event scan consumes and clears them.
enum PairState : std::uint8_t { kInteracting = 1, kTouching = 2, kStarted = 4, kEnded = 8 };

struct PairList {
  std::vector<std::uint32_t> i, j;
  std::vector<SpringHistory> history;
  std::vector<RollingHistory> rolling;  // read and written only by laws with a rolling model
  std::vector<ContactTally> tally;
  std::vector<ContactRecord> record;
  std::vector<std::uint8_t> state;   // PairState bits of the last evaluation
  std::vector<std::uint32_t> first;  // pairs with i == p: [first[p], first[p+1])
  // The j side, in j order: slots jfirst[p] .. jfirst[p+1] hold the pairs with j == p (ascending
  // pair index), jslot[k] is pair k's slot, and j_force/j_torque the force and torque on j of its
  // last evaluation (zero unless interacting). The pair pass writes them scattered; the particle
  // pass then reads each particle's slots in one run instead of chasing pair indices (measured on
  // the bench bed: the chased loads were a fifth of the particle pass).
  std::vector<std::uint32_t> jfirst, jslot;
  std::vector<Vec3> j_force, j_torque;

  std::vector<std::uint32_t> j_scratch, j_hist;  // build_transpose's, kept (not list state)

  std::size_t size() const { return i.size(); }
  /// n pairs with zeroed springs, tallies, records and states (i and j keep whatever they held: the
  /// caller writes them); the j side is sized by build_transpose. build_pairs resets every field,
  /// so a list may be rebuilt in the storage of an older one: a new field must be reset there too.
  void resize(std::size_t n);
  /// Builds jfirst/jslot from (i, j) for n_particles particles (stable: ascending pair index) and
  /// zeroes the j-side loads: a counting sort of the pairs by j in two levels, in parallel.
  void build_transpose(std::size_t n_particles);
};

/// Particle indices sorted into cells (stable in particle index), with the occupied cells listed:
/// building, renumbering and looking a cell up cost O(particles), not O(cells). The particles are
/// sorted by cell with a radix sort (KeySort); `slot` maps a cell to its entry in `cell` as a
/// sparse set (Briggs and Torczon 1993): an entry is trusted only if `cell` points back at the
/// cell, so it is never cleared, and only occupied cells are written. Keep one CellList across
/// rebuilds: `slot` is the one array of the grid's size, allocated (and zeroed) once per grid
/// size.
struct CellList {
  CellGrid grid;
  std::vector<std::uint32_t> items;      // particles by (cell, index)
  std::vector<std::uint32_t> item_cell;  // the cell of items[s]
  std::vector<std::uint32_t> cell;       // the occupied cells, ascending
  std::vector<std::uint32_t> begin;      // occupied cell s holds items[begin[s] .. begin[s + 1])
  std::vector<std::uint32_t> slot;       // grid cell -> its index in `cell`, if occupied
  KeySort sorter;

  void build(const std::vector<Vec3>& x, const CellGrid& g);
  /// The same list after the particles were reordered or removed: old particle k is now inv[k]
  /// (UINT32_MAX if removed), and inv keeps the order of the particles of each cell (as a
  /// spatial sort by this list and the removal of particles do). No second sort.
  void renumber(const std::vector<std::uint32_t>& inv);
  /// The occupied-cell entry of grid cell c, or UINT32_MAX if it holds no particle.
  std::uint32_t find(std::size_t c) const {
    const std::uint32_t s = slot[c];
    return s < cell.size() && cell[s] == c ? s : UINT32_MAX;
  }

 private:
  void index_cells();  // cell, begin and slot from item_cell
};

/// Order of particles by cell (stable): new[k] = old[order[k]]. Improves cache locality.
std::vector<std::uint32_t> spatial_order(const std::vector<Vec3>& x, const CellGrid& g);

/// Rebuilds the (i, j) list: pairs with |x_j - x_i| < r_i + r_j + extra. History arrays are reset.
void build_pairs(const std::vector<Vec3>& x, const std::vector<double>& r, const Domain& d,
                 const CellList& cells, double extra, PairList& out);

/// Moves the state of pairs in contact from `old` into `fresh`. `inv` maps an old particle index to
/// its new index (UINT32_MAX if removed); a contact whose partner was removed ends.
void carry_over(const PairList& old, const std::vector<std::uint32_t>& inv, PairList& fresh);

}  // namespace lbdem::dem

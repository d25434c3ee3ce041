#pragma once
// The gas solver: owns the lattice, populations, geometry flags, wall bodies and force field, and
// advances them one stream-collide step at a time. Lattice units throughout (dx = dt = 1); the SI
// conversion lives in units.hpp (LatticeUnits, with the tau/Mach/pressure checks) and in the
// scenarios.
//
// A step: the velocity next to each outlet (open_boundary.hpp), the kernel (stream_collide.hpp)
// for the operator and forcing in use, then each body's links: bounce-back for walls and velocity
// inlets (bounce_back.hpp), anti-bounce-back for density outlets, and on a box face with a slip
// fraction the blend of bounce-back and specular reflection (slip_wall.hpp) on the links that have
// a specular partner; they also give its momentum-exchange force and the mass it passed to the
// fluid. Last, the mass sources.
#include "core/types.hpp"
#include "lbm/aa_pattern.hpp"
#include "lbm/boundary/bounce_back.hpp"
#include "lbm/boundary/box_faces.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/boundary/open_boundary.hpp"
#include "lbm/boundary/slip_wall.hpp"
#include "lbm/boundary/wall_function.hpp"
#include "lbm/cell.hpp"
#include "lbm/collision/collision_model.hpp"
#include "lbm/fluid_runs.hpp"
#include "lbm/forcing/guo.hpp"
#include "lbm/grid.hpp"
#include "lbm/lattice_fields.hpp"
#include "lbm/level_flux.hpp"
#include "lbm/pdf_field.hpp"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace lbdem::lbm {

/// A cell the watchdog rejected [lattice units].
struct UnhealthyCell {
  int x, y, z;
  double rho, speed;
};

struct LbmSettings {
  int nx = 0, ny = 0, nz = 0;  // interior cells
  BoxFaces faces = BoxFaces::all_periodic();
  CollisionModel collision = Bgk{1.0};
  Vec3 body_force = Vec3::Zero();  // uniform force density [lattice units]
  double wall_density = 1.0;       // rho_w of Ladd's moving-wall term [lattice units]
  // Precision of the populations, of the kernel's per-cell fields and of its arithmetic
  // (lattice_fields.hpp); double is the reference mode.
  Precision precision = Precision::float64;
};

class LbmSolver {
 public:
  explicit LbmSolver(const LbmSettings& s);

  const LbmSettings& settings() const { return settings_; }
  const Grid& grid() const { return flags_.grid(); }
  long steps() const { return steps_; }
  AaState state() const { return state_; }
  Precision precision() const { return settings_.precision; }
  const FlagField& flags() const { return flags_; }
  /// The populations of cell (x, y, z) as the next collision reads them (either AA state).
  void cell_populations(int x, int y, int z, double (&f)[kQ]) const;

  // --- Geometry ---------------------------------------------------------------------------------
  /// A new solid body (id >= 1) with its wall velocity (none: at rest). Box wall faces are bodies
  /// created by the constructor, named after the face.
  int add_body(std::string name, WallVelocity u = {});
  int body_count() const { return int(bodies_.size()); }
  const std::string& body_name(int body) const { return bodies_[std::size_t(body - 1)].name; }
  /// Body id of a box face, 0 if the face is periodic.
  int face_body(int face) const { return face_body_[std::size_t(face)]; }
  /// Slip fraction of a body: FaceBoundary::slip of its box face, 0 for any other body.
  double wall_slip(int body) const { return bodies_[std::size_t(body - 1)].slip; }
  /// Makes an interior cell solid (body >= 1) or fluid again (0). Links are rebuilt before the next
  /// step; a cell that turns fluid keeps whatever populations it holds.
  void set_cell(int x, int y, int z, int body);
  /// Ignored by outlets, whose velocity is free. Throws std::invalid_argument for a moving
  /// velocity on a slip face (FaceBoundary::slip > 0).
  void set_wall_velocity(int body, WallVelocity u);
  /// A velocity inlet: a body whose bounce-back links carry Ladd's term at the inflow velocity u
  /// (at each link's half-way point) and the wall density; its cells come from set_cell, as for
  /// add_body, or from a box face of kind inlet. The same as add_body(name, u), named for intent.
  int add_inlet(std::string name, WallVelocity u);
  /// A density outlet: a body whose links apply anti-bounce-back at density rho_out (> 0), i.e.
  /// pressure rho_out c_s^2 [lattice units]; its cells come from set_cell or a box face.
  int add_outlet(std::string name, double density);
  bool is_outlet(int body) const { return bodies_[std::size_t(body - 1)].outlet_density > 0; }
  void set_outlet_density(int body, double density);
  /// Whether the outlet extrapolates the velocity of its bracket to the half-way points (default)
  /// or takes the cell's (boundary/open_boundary.hpp: off where a strong swirl crosses it).
  void set_outlet_extrapolation(int body, bool on);
  /// Whether gas may enter through the outlet (default) or its inflowing cells bounce back
  /// (boundary/open_boundary.hpp: a swirl's core drawing gas in).
  void set_outlet_backflow(int body, bool allowed);
  /// Werner & Wengle's wall function on a body at rest (boundary/wall_function.hpp): its links
  /// impose the law-of-the-wall stress at the molecular viscosity of the collision model in use
  /// instead of no slip. For under-resolved LES walls; throws std::invalid_argument for an outlet
  /// or a body with a wall velocity.
  void set_wall_function(int body, bool on);
  bool has_wall_function(int body) const { return bodies_[std::size_t(body - 1)].wall_function; }
  /// The point torques on a body are taken about [lattice coordinates]; default the origin.
  void set_body_origin(int body, const Vec3& x) { bodies_[std::size_t(body - 1)].origin = x; }

  // --- State ------------------------------------------------------------------------------------
  /// Equilibrium populations from init(x, y, z, rho, u) on fluid cells, rest equilibrium at the
  /// wall density elsewhere (ghosts, solids); resets to the natural state.
  void initialize(const std::function<void(int x, int y, int z, double& rho, Vec3& u)>& init);
  void step();
  /// Every slot of the population array as stored (float slots widened to double: f_q - w_q,
  /// pdf_field.hpp), padding included: with state() and steps() a checkpoint, and the array that
  /// bitwise comparisons compare. Widening and narrowing back are exact.
  std::vector<double> stored_slots() const;
  /// Restores the slots, AA state and step count saved from stored_slots(), state() and steps();
  /// throws std::invalid_argument if the size does not match this lattice.
  void load_state(const std::vector<double>& slots, AaState s, long steps);

  /// The watchdog: the first fluid cell (storage order) whose density leaves [rho_min, rho_max]
  /// or whose speed exceeds u_max, or whose moments are not finite; nullopt if all are sane.
  /// Costs about one step (a read-only pass); bitwise the same answer for any thread count.
  std::optional<UnhealthyCell> find_unhealthy(double rho_min, double rho_max, double u_max) const;

  void set_collision(const CollisionModel& c) { settings_.collision = c; }
  void set_body_force(const Vec3& f) { settings_.body_force = f; }
  /// Per-cell force density (SoA over storage cells, Grid::index), zero when first enabled.
  void enable_force_field();
  bool has_force_field() const;
  void set_cell_force(int x, int y, int z, const Vec3& f);

  /// The porous-medium form (forcing/porous.hpp, Guo & Zhao 2002): per-cell fluid fraction eps and
  /// Darcy drag alpha = mu eps / K [lattice units; eps nu / K per step at rho = 1], 1 and 0 when
  /// first enabled; a uniform Forchheimer
  /// coefficient beta = eps F_eps / sqrt(K). Call initialize() after setting eps if the gas
  /// starts in motion, so that its equilibrium carries the 1/eps terms.
  void enable_porosity();
  bool has_porosity() const { return !eps_.empty(); }
  void set_cell_porosity(int x, int y, int z, double eps, double alpha = 0);
  void set_forchheimer(double beta);
  /// Sums, over the steps since the last take_velocity_sum, of the intrinsic velocity u / eps each
  /// collision used [lattice units], kept by the kernel itself (porous form only: a no-op
  /// otherwise). take_velocity_sum returns them over interior cells in compact order and restarts
  /// the sums; the number of steps they hold is the caller's to count.
  void enable_velocity_sum();
  bool has_velocity_sum() const;
  void take_velocity_sum(std::vector<Vec3>& out);
  /// The sums as take_velocity_sum returns them, left running; and sums put back (a checkpoint
  /// written inside an exchange interval): interior cells in compact order, solid cells ignored.
  void velocity_sum(std::vector<Vec3>& out) const;
  void set_velocity_sum(std::span<const Vec3> sum);
  /// Whole fields at once, over interior cells in compact order (Grid::compact_index), as the
  /// coupling exchanges them: eps in (0, 1] and alpha >= 0 (checked; std::invalid_argument naming
  /// the first bad cell), force density [lattice units]. Solid cells are skipped.
  void set_porosity_field(std::span<const double> eps, std::span<const double> alpha);
  void set_force_field(std::span<const Vec3> force);
  /// Mass sources: every step adds `mass` [lattice units; negative: a sink, which must not drain
  /// the cell] to each listed fluid cell as resting
  /// equilibrium populations (w_q mass), after the collision and the boundary links, so that
  /// total_mass() grows by exactly their sum per step and the momentum is untouched (a source that
  /// carries momentum pairs with the force field). Replaces the previous list; throws
  /// std::invalid_argument for a cell that is not an interior fluid cell or a non-finite mass.
  struct MassSource {
    int x, y, z;
    double mass;
  };
  void set_mass_sources(std::vector<MassSource> sources);
  /// A mass source in every interior cell at once (compact order, mass per step [lattice units];
  /// empty: none), applied as set_mass_sources' are and beside them; solid cells must hold 0. The
  /// coupling's displaced gas (coupling/coupler.hpp) is one. Throws std::invalid_argument for a
  /// wrong size, a non-finite entry or a nonzero one in a solid cell.
  void set_mass_source_field(std::span<const double> mass);
  /// Sum of the sources' mass per step, listed and field [lattice units].
  double mass_source_rate() const;
  /// Fluid fraction over interior cells in compact order (1 without porosity, 0 in solids).
  void porosity(std::vector<double>& eps) const;

  // --- Results ----------------------------------------------------------------------------------
  /// Momentum-exchange force of the fluid on a body during the last step [lattice units].
  const Vec3& wall_force(int body) const { return bodies_[std::size_t(body - 1)].load.force; }
  /// The mean of wall_force() over the last two steps, what an output row should report. Near
  /// tau = 1/2 the non-equilibrium populations flip sign every step (omega near 2), and one step's
  /// momentum exchange carries half of that period-2 oscillation, its sign set by the step's
  /// parity: on a 5 x 3-cell duct at Re 360 with LES at tau - 1/2 = 1e-4, one step's forces were
  /// off by 5 % of the pressure drop (inlet) and 8 % (walls), and failed to balance the gas's
  /// momentum by 13 % of the wall force; the mean of two steps balances it to round-off. 0 before
  /// the first step.
  Vec3 wall_force_mean2(int body) const {
    const Body& b = bodies_[std::size_t(body - 1)];
    return 0.5 * (b.load.force + b.previous_force);
  }
  /// Its torque about the body's origin (set_body_origin) [lattice units].
  const Vec3& wall_torque(int body) const { return bodies_[std::size_t(body - 1)].load.torque; }
  /// Mass that entered the fluid through the body's links during the last step (negative:
  /// leaving) [lattice units, mass per step]: the inflow of an inlet, minus the outflow of an
  /// outlet; 0 for a wall at rest, round-off for one moving in its own plane. Over steps, the
  /// change of total_mass() is the sum of these over all bodies plus mass_source_rate(), to
  /// round-off.
  double mass_flow(int body) const { return bodies_[std::size_t(body - 1)].load.mass; }
  CellMoments moments(int x, int y, int z) const;
  /// Fields over interior cells in compact order; solid cells read 0.
  void density(std::vector<double>& rho) const;
  void velocity(std::vector<Vec3>& u) const;
  /// sum_q c_q f_q / rho: the populations' velocity without the half-force shift or the porous
  /// form's implicit drag, a function of the populations alone.
  void raw_velocity(std::vector<Vec3>& u) const;
  /// density() and raw_velocity() in one pass over the populations.
  void raw_moments(std::vector<double>& rho, std::vector<Vec3>& u) const;
  /// Sum of rho over fluid cells, bitwise independent of the thread count.
  double total_mass() const;
  /// The fluid's mass ledger [lattice units]: total_mass() when initialize() last ran, and the
  /// mass every body's links and the mass sources have given the fluid since (the sum of
  /// mass_flow() over bodies and steps, plus the sources). total_mass() - initial_mass() -
  /// exchanged_mass() is round-off in any run: the gas creates or loses no mass of its own. A
  /// checkpoint stores both (set_mass_ledger).
  double initial_mass() const { return initial_mass_; }
  double exchanged_mass() const { return exchanged_mass_; }
  void set_mass_ledger(double initial, double exchanged) {
    initial_mass_ = initial;
    exchanged_mass_ = exchanged;
  }
  /// Sum over fluid cells of sum_q c_q f_q, the momentum before the half-force shift [lattice
  /// units]: a step adds exactly the sum of the cell forces (and the wall and open-boundary
  /// exchanges) to it, so it is the gas's half of a momentum balance that closes to round-off.
  /// Bitwise independent of the thread count.
  Vec3 raw_momentum() const;
  /// Mass that crossed nested surfaces link by link during the last step (level_flux.hpp): flux[k]
  /// entered the cells of level >= k [lattice units, per step]; the mass sources' share of the
  /// populations is not counted as crossing.
  std::vector<double> level_flux(std::span<const int> level, int levels) const;

 private:
  struct Body {
    std::string name;
    WallVelocity velocity;
    BounceBackLinks links;
    Vec3 origin = Vec3::Zero();
    WallLoad load;
    Vec3 previous_force = Vec3::Zero();  // load.force of the step before
    double outlet_density = 0;           // > 0: a density outlet
    PressureOutlet outlet;               // its velocity samples, built with the links
    bool outlet_extrapolate = true;
    bool outlet_backflow = true;
    bool wall_function = false;
    WallFunctionCells wall_cells;  // built with the links when wall_function is on
    double slip = 0;               // > 0: a slip face, whose inward normal is slip_sign e_axis
    int slip_axis = 0, slip_sign = 1;
    SlipLinks slip_links;  // split from `links` when they are built; the rest bounce back
  };
  void rebuild_links();
  void add_mass_sources();
  /// Adds the source field's pending step to the populations, if one is pending: every reader of
  /// the populations outside step() calls it first, so that they see what the next step reads.
  void settle_mass_sources() const;
  void add_mass_source_field();
  void set_wall_velocity_terms(Body& b);
  /// Calls fn(forcing) with the cheapest policy that represents the current forces, its per-cell
  /// fields those of lat; with `accumulate`, a porous policy also adds to the velocity sums (the
  /// collision of a step only).
  template <class T, class Fn>
  void with_forcing(const LatticeFields<T>& lat, Fn&& fn, bool accumulate = false) const;
  /// The collision of one step with operator op over the fluid runs (solver_passes.hpp).
  template <class Op>
  void collide_pass(const Op& op);

  /// Calls fn(lattice) or fn(pdf) with the fields in their precision.
  template <class Fn>
  decltype(auto) with_lattice(Fn&& fn) const {
    return std::visit([&](const auto& l) -> decltype(auto) { return fn(l); }, lat_);
  }
  template <class Fn>
  decltype(auto) with_lattice(Fn&& fn) {
    return std::visit([&](auto& l) -> decltype(auto) { return fn(l); }, lat_);
  }
  template <class Fn>
  decltype(auto) with_pdf(Fn&& fn) const {
    return with_lattice([&](const auto& l) -> decltype(auto) { return fn(l.pdf); });
  }
  template <class Fn>
  decltype(auto) with_pdf(Fn&& fn) {
    return with_lattice([&](auto& l) -> decltype(auto) { return fn(l.pdf); });
  }

  LbmSettings settings_;
  std::variant<LatticeFields<double>, LatticeFields<float>> lat_;
  FlagField flags_;
  std::vector<Body> bodies_;
  std::array<int, 6> face_body_{};
  std::vector<MassSource> mass_sources_;
  std::vector<double> mass_source_field_;    // per interior cell, compact order; empty: none
  double mass_source_field_sum_ = 0;         // its sum, bitwise independent of the thread count
  std::vector<double> mass_source_storage_;  // the field per storage cell (what the kernels read)
  // The field's share of the last step, not yet in the populations: the next step's collision
  // adds it as it loads them (forcing/mass_source.hpp), or settle_mass_sources() before anything
  // else reads them.
  mutable bool mass_pending_ = false;
  std::vector<double> eps_;  // per storage cell, when porosity is enabled (the kernel reads 1/eps)
  // Whether the lattice keeps rho and u / eps of the last collision (a body has the wall function).
  bool keep_moments_ = false;
  double beta_ = 0;
  AaState state_ = AaState::natural;
  long steps_ = 0;
  double initial_mass_ = 0, exchanged_mass_ = 0;
  bool links_dirty_ = true;
  FluidRuns runs_;  // the cells the collision visits, rebuilt with the links
};

}  // namespace lbdem::lbm

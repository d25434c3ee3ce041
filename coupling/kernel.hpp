#pragma once
// The particle <-> lattice kernel of unresolved coupling: particle volume -> gas fraction eps,
// per-particle forces -> force density, and cell fields -> values at the particles, all through
// one kernel so that deposition and interpolation are adjoint (momentum is conserved to round-off
// and a constant field is read back exactly).
//
// Kernel (two-step filtering, as in Capecelatro & Desjardins 2013, J. Comput. Phys. 238, 1, and
// Sun & Xiao 2015, Int. J. Multiphase Flow 77, 142, with an explicit compact filter in place of
// their diffusion step): a particle first shares its quantity among the 8 cells around it with
// trilinear (cloud-in-cell) weights w_c, then each such source cell c spreads its share over the
// gas cells c' with the separable filter G(c' - c) = g(dx) g(dy) g(dz):
//   K_p(c') = sum_c w_c(x_p) post(c') G(c' - c) pre(c).
// Periodic axes wrap; the faces of a non-periodic axis are mirrors: a tap beyond a face reads the
// cell it reflects to (more than once if the kernel is wider than the box), so G stays symmetric
// with unit row and column sums. Solid cells (m = 0) receive nothing: post = m d and
// pre = 1 / (G m d), with d the symmetric balancing d (G m d) = 1 on the gas cells (d = 1 without
// solid cells). Where the particles' box is not the grid (an edge of round(L/dx) cells centred on
// it, scenarios/common/fluid_config.cpp), a cell of the outer layer holds the particles of the
// part of the box it stands for, a = 0.75-1.25 of a cell (more than its own volume where the grid
// is smaller than the box, less where it sticks out): m = a there, so that a bed of uniform solid
// fraction phi deposits phi a dx^3 in each cell, and the solid fraction is the deposit over
// a dx^3 (docs/physics.md, Coupling kernel). So each column sums to 1 exactly, sum_c' K_p(c') = 1
// to round-off wherever a particle is (volume and force conserved at walls, solids and faces), and
// each row sums to 1 to the balance error: a bed of uniform solid fraction deposits a uniform field
// up to walls and solids. The alternative, renormalising each source cell over the gas cells it
// reaches (G / Z(c)), conserves too but piles the share of the cells next to a wall onto the cells
// a little further in: on a settled bed in a 3-cell-thin walled box (test_kernel_walls.cpp) it read
// a solid fraction of 0.68 in the middle layer and 0.52 at the walls, where binning the beads
// gives 0.58 and 0.545; this kernel reads 0.55 in both. A particle reads a field back with the same
// K_p, so deposition and interpolation are transposes of each other. K_p is continuous and
// piecewise multilinear in x_p, so eps and the force density follow a moving particle without
// jumps. g is the triweight (1 - (k/R)^2)^3 sampled at the integer offsets |k| < R: C2 and
// compactly supported, unlike a Gaussian truncated at 3 sigma (whose cut-off steps are 1 % of the
// peak), and symmetric, so a linear field is interpolated exactly away from walls (sum_k k g(k) = 0
// and the trilinear weights reproduce x_p). R is set so that the kernel's variance per axis,
// averaged over the position within a cell, is sigma^2: var(g) + 1/6 (the trilinear part adds f(1 -
// f)). Cost, and why two steps rather than a kernel evaluated per particle: 8 weights per particle
// and quantity, plus 3 (2H + 1) taps per cell and component (H = ceil(R) - 1: 5 taps at
// sigma = dx, 11 at 2 dx), whatever the number of particles. A per-particle 3-D kernel of the same
// reach costs (2H + 2)^3 per particle (1728 cells at sigma = 2 dx), which in a dense bed (tens of
// particles per cell) is 10^4 operations per cell and quantity against about 10^2 here.
//
// Determinism: nothing is scattered with atomics. locate() bins the particles by their lower
// trilinear cell with a serial counting sort (stable, by particle index); deposition then adds,
// for each cell, the terms of its 8 bins in a fixed order (corner by corner, a cell plane per
// thread), and every filter pass writes each cell from one thread with taps in a fixed order.
// Results are bitwise the same for any OpenMP thread count (not for a permuted particle list: that
// reorders the sums within a bin, a round-off change).
//
// Units: SI at the interface (positions [m], radii [m], fields as given); fields are over the
// interior cells in compact order (Grid::compact_index, x fastest), as LbmSolver::velocity() and
// density() return them.
#include "core/types.hpp"
#include "lbm/boundary/flags.hpp"
#include "lbm/geometry/lattice_frame.hpp"
#include "lbm/grid.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace lbdem::coupling {

/// Default kernel width sigma per parcel diameter D, used as sigma = max(dx, 2 D). The particle's
/// own reaction slows the gas where it sits by about 0.28 D / sigma of the slip (docs/physics.md,
/// Coupling kernel; Maxey & Patel 2001, Int. J. Multiphase Flow 27, 1603, force coupling: u_self =
/// F / (6 pi mu sqrt(pi) sigma) against Stokes drag 3 pi mu D u_slip), 14 % at sigma = 2 D; the
/// Poisson noise of the solid fraction of a random bed, sd(phi)/phi = sqrt(V_p int K^2 / phi) =
/// sqrt(0.524 D^3 / (49.7 sigma^3 phi)) for this kernel (49.7 = 1 / int K^2 in units of sigma^3; a
/// Gaussian has 44.5), is 4.7 % at phi = 0.6 and sigma = 2 D (13 % at sigma = D). The floor dx
/// keeps the kernel resolved (5 taps at sigma = dx) and the eps history of a moving particle smooth
/// (see the test); for D <= dx / 2 it already gives sigma >= 2 D. Wider kernels smear the bed
/// surface and wall layers over about 2 sigma. For a coarse-grained parcel of l^3 originals (D = l
/// d_o) the drag, and so the error, is l^3 times one original's: 0.28 l^3 d_o / sigma, 0.14 l^2 at
/// the default; keeping 14 % needs sigma = 2 l^2 D, which the caller may pass (docs/physics.md,
/// Coupling kernel).
inline constexpr double kDefaultWidthPerDiameter = 2.0;
inline double default_kernel_width(double dx, double parcel_diameter) {
  const double w = kDefaultWidthPerDiameter * parcel_diameter;
  return w > dx ? w : dx;
}

/// Default lower bound of the gas fraction. Random close packing of equal spheres is eps = 0.36
/// and packed beds sit at 0.36-0.40 (Ergun's data); a kernel average of a real bed goes below that
/// only through sampling noise (about 0.03 at the default width) or overlapping parcels. The
/// bound keeps the closures finite (Wen-Yu drag ~ eps^-3.65 is 1.9x its eps = 0.36 value at 0.3)
/// and the 1/eps terms of the porous LBM form (lbm/forcing/porous.hpp) within a factor 3.3.
inline constexpr double kDefaultEpsMin = 0.3;

/// The particles' box where it differs from the gas grid along a non-periodic axis by less than a
/// cell: each face of the grid within a cell of the box's (periodic axes are the grid's).
struct ParticleBox {
  Vec3 lo, hi;  // [m]
};

/// What gas_fraction() clipped.
struct PorosityReport {
  Index clipped = 0;                        // gas cells where 1 - phi < eps_min, set to eps_min
  std::array<int, 3> first = {-1, -1, -1};  // the first of them in compact order (x fastest)
  double lowest = 1.0;                      // smallest 1 - phi before clipping
};

/// Not thread-safe: its const calls reuse internal buffers, so one kernel serves one caller at a
/// time (each call is parallel inside).
class ParticleKernel {
 public:
  /// Below these sizes a loop runs on one thread: an OpenMP region costs microseconds (milliseconds
  /// on an oversubscribed machine), more than the work, and a particle sweep makes dozens. Results
  /// do not depend on it (every loop writes each entry from one thread in a fixed order, and the
  /// clipping report of gas_fraction() is a count, a least index and a least value).
  static constexpr Index kMinParallelCells = 4096;
  static constexpr std::size_t kMinParallelParticles = 1024;

  /// width: sigma [m], at least frame.dx (std::invalid_argument otherwise). solid: one byte per
  /// interior cell in compact order, nonzero where there is no gas; empty: every cell is gas.
  /// box: the particles' box, if its faces are not the grid's (std::invalid_argument if one lies
  /// a cell or more from the grid's); a face within 1e-9 of a cell of the grid's is the grid's.
  /// Fewer than 2^32 - 1 cells (32-bit cell indices; std::invalid_argument otherwise).
  ParticleKernel(const lbm::Grid& grid, const lbm::LatticeFrame& frame, double width,
                 std::span<const std::uint8_t> solid = {},
                 const std::optional<ParticleBox>& box = std::nullopt);

  /// The solver's geometry as a solid mask for the constructor (interior cells, compact order).
  static std::vector<std::uint8_t> solid_mask(const lbm::FlagField& flags);

  double width() const { return width_; }                    // sigma [m]
  double support_radius() const { return radius_ * dx_; }    // R of the triweight [m]
  int half_taps() const { return half_; }                    // H: filter offsets -H..H [cells]
  const std::vector<double>& taps() const { return taps_; }  // g(0..H), sum over -H..H is 1
  double cell_volume() const { return dx_ * dx_ * dx_; }     // [m^3]

  /// Per cell (compact order): the part of the particles' box it stands for, in cells (a product
  /// of 0.75-1.25 per axis in the outer layer of a grid centred on a box of other size, 1
  /// elsewhere), 0 in solid cells: the kernel's fluid weight m.
  const std::vector<double>& accessible() const { return volume_; }

  /// Places the particles (positions [m]): trilinear weights and cell bins, reused by every
  /// deposit and interpolation until the next call. Positions outside the grid on a non-periodic
  /// axis (a box larger than the grid) are taken at the grid's face, which hands them to the
  /// outer cell that stands for them; periodic axes wrap. O(N) with a serial counting sort.
  void locate(std::span<const Vec3> positions);
  std::size_t particle_count() const { return weight_.size(); }
  /// Largest |d (G m d) - 1| over the gas cells after the balancing: how far a uniform source
  /// field deposits off uniform (0 without solid cells).
  double balance_error() const { return balance_error_; }
  /// The balancing stops below kBalanceTolerance or after kBalanceIterations filter passes.
  static constexpr double kBalanceTolerance = 1e-12;
  static constexpr int kBalanceIterations = 400;

  /// Particles with no gas cell within the kernel (buried in a solid block thicker than the
  /// kernel): they deposit nothing and read 0. The first is the lowest index, -1 if none.
  std::size_t unmapped_count() const { return unmapped_; }
  Index first_unmapped() const { return first_unmapped_; }

  /// Gas fraction eps = 1 - phi per cell, phi = sum_p V_p K_p / (a dx^3) with V_p = 4/3 pi r_p^3
  /// and a = accessible(): a parcel's own radius already holds its originals' volume, so no
  /// multiplicity enters. Clipped below at eps_min; solid cells read 1 (they hold no particle
  /// volume). The particles' volume is sum_c (1 - eps) a dx^3 where nothing is clipped.
  PorosityReport gas_fraction(std::span<const double> radii, double eps_min,
                              std::vector<double>& eps) const;

  /// Density per unit volume of per-particle quantities q_p: out(c) = sum_p q_p K_p(c) / dx^3
  /// (e.g. forces [N] -> force density [N/m^3]); sum_c out(c) dx^3 = sum_p q_p to round-off. Per
  /// gas cell volume dx^3, also in an outer cell whose a is not 1: that cell's gas receives
  /// exactly what its particles give (momentum to round-off).
  void deposit(std::span<const double> q, std::vector<double>& out) const;
  void deposit(std::span<const Vec3> q, std::vector<Vec3>& out) const;
  /// Both deposits at once (one filter over four components, bitwise the same as two calls).
  void deposit(std::span<const double> q, std::span<const Vec3> v, std::vector<double>& out_q,
               std::vector<Vec3>& out_v) const;

  /// Values at the particles of a cell field (compact order; solid cells are not read):
  /// out_p = sum_c K_p(c) field(c). Exact for a constant field; for a linear one wherever the
  /// kernel reaches neither a face nor a solid cell (symmetric taps, trilinear weights) and the
  /// balancing leaves d = 1 (no solid cells in the grid and a = 1 in every cell; near solids and
  /// faces d decays to 1 within a few kernel widths).
  void interpolate(std::span<const double> field, std::vector<double>& out) const;
  void interpolate(std::span<const Vec3> field, std::vector<Vec3>& out) const;
  /// Both interpolations at once (one filter over four components, bitwise the same as two calls).
  void interpolate(std::span<const double> field, std::span<const Vec3> vfield,
                   std::vector<double>& out, std::vector<Vec3>& vout) const;

  /// Trilinear interpolation over the gas corners of each particle's cell (weights renormalised
  /// over them), without the filter: for a value needed only locally, where the exchange does not
  /// need the adjoint of deposit() (the gas velocity a drag coefficient is evaluated at; eps and
  /// grad p go through interpolate(), coupler.cpp). Exact for constant and linear fields away
  /// from solids.
  void interpolate_local(std::span<const double> field, std::vector<double>& out) const;
  void interpolate_local(std::span<const Vec3> field, std::vector<Vec3>& out) const;

  /// grad p per gas cell [Pa/m] from the cell pressure p [Pa]: central differences, one-sided
  /// (first order) where one neighbour is solid or outside the box, 0 where both are. One-sided
  /// rather than zero-flux because the gas pressure next to a wall is not flat (hydrostatic head,
  /// the Ergun drop of a bed): both forms are exact for a linear p. Solid cells read 0.
  /// reached_only: only on the z planes the located particles' kernel reaches (the others read
  /// 0), which are all that interpolate() reads of it at those particles.
  void pressure_gradient(std::span<const double> p, std::vector<Vec3>& grad,
                         bool reached_only = false) const;
  /// The divergence of a flux field j per gas cell [1/dx units of j] in conservative form:
  /// div(c) = sum over c's six faces of the outward face flux / dx, the face flux the mean of the
  /// two cells' normal components, 0 on faces to a solid cell or out of a non-periodic box (no
  /// particle crosses a wall). Each face's flux leaves one cell and enters the other, so the sum
  /// of div over the cells is 0 up to round-off. Solid cells read 0. (kernel_divergence.cpp)
  void divergence(std::span<const Vec3> j, std::vector<double>& div) const;

 private:
  // Fields of nc components are interleaved: component a of cell c at c * nc + a. Each component
  // is filtered exactly as a scalar field alone would be (the same taps in the same order).
  // The z planes a pass filters (on) and those it sets to 0 (off), ascending.
  struct PlaneLists {
    std::vector<int> on, off;
  };
  // One filter pass along `axis`: out(c) = sum_k g(|k|) in(c + k e_axis), taps in a fixed order,
  // on the planes listed on; the planes listed off read 0. The passes share their loops among the
  // threads of the enclosing parallel region of filter() (orphaned worksharing): out must already
  // have in's size.
  void filter_axis(const std::vector<double>& in, std::vector<double>& out, int axis,
                   const PlaneLists& planes, int nc) const;
  // filter_axis for axis 1 or 2 (a plane at a time), on the listed planes.
  void filter_planes(const std::vector<double>& in, std::vector<double>& out, int axis,
                     const std::vector<int>& active, int nc) const;
  // The z planes where `planes` is nonzero (active; all if null) or zero (not active), ascending.
  std::vector<int> listed_planes(const std::uint8_t* planes, bool active) const;
  // Sets the listed planes of a field of nc components to 0 (shared as filter_axis, no barrier).
  void zero_planes(const std::vector<int>& list, std::vector<double>& out, int nc) const;
  // G * in over all three axes (in is overwritten as scratch): the x and y passes on the planes
  // `xy`, the z pass on the planes `z` (null: all). Skipping a plane changes no bit of what is
  // computed elsewhere: a deposit's x and y passes see only zeros off the particles' planes, and
  // an interpolation samples only those planes.
  void filter(std::vector<double>& in, std::vector<double>& out, int nc,
              const std::uint8_t* xy = nullptr, const std::uint8_t* z = nullptr) const;
  // Source cells of NC components: src(c, a) = pre(c) sum_p w_c(x_p) q_p[a], the terms of each
  // cell's 8 bins added corner by corner; qs holds the NC values of each particle in bin order.
  template <int NC>
  void gather_sources(const std::vector<double>& qs, std::vector<double>& src) const;
  // out[NC p + a] = sum_c w_c(x_p) v(c, a) over the 8 trilinear cells of each particle p.
  template <int NC>
  void sample(const double* v, double* out) const;
  // As sample, divided by the gas weight.
  template <int NC>
  void sample_local(const double* field, double* out) const;
  // v = pre (G * (post in)), the field each source cell reads (in, of nc components, is
  // overwritten).
  void smooth(std::vector<double>& in, std::vector<double>& v, int nc) const;
  // smooth() of a copy of field (nc values per cell), in work_out_.
  const std::vector<double>& smoothed(const double* field, int nc) const;
  // The deposit of NC components per particle (qs: NC values per particle, in particle order),
  // unscaled: G * src, in work_out_ (qs may be work_q_).
  template <int NC>
  const std::vector<double>& deposit_components(const double* qs) const;
  Index cell(int x, int y, int z) const { return grid_.compact_index(x, y, z); }

  lbm::Grid grid_;
  lbm::LatticeFrame frame_;
  double width_, dx_;
  double radius_ = 0;  // triweight half-width R [cells]
  int half_ = 0;       // H
  std::vector<double> taps_;
  // Sets pre_ and post_ (and balance_error_) from the mask and the filter.
  void balance();

  std::vector<std::uint8_t> gas_;  // 1 on gas cells, 0 on solid ones
  std::vector<double> volume_;     // m per cell: accessible(), 0 on solid cells
  std::vector<double> pre_;        // 1 / (G m d) per source cell, 0 where no gas is in reach
  std::vector<double> post_;       // m d per receiving cell
  double balance_error_ = 0;
  // Per axis and coordinate i: the (neighbour coordinate, tap) pairs of the filter, k = -H..H,
  // wrapped on periodic axes, mirrored at the faces of a non-periodic one.
  struct Tap {
    int j;
    double g;
  };
  std::array<std::vector<std::vector<Tap>>, 3> tap_list_;

  // From locate(), in bin order (slot k holds particle bin_items_[k]): the 8 corner weights
  // (corner a + 2 b + 4 c is the lower trilinear cell + (a, b, c), wrapped), zero on corners off
  // the gas and outside a non-periodic box, and the corners' cells, found once for every deposit
  // and sample that follows (a dozen per exchange; 0 where the weight is 0).
  std::array<int, 3> bins_{};             // bins per axis: n, or n + 1 on a non-periodic axis
  std::vector<Index> bin_start_;          // CSR over bins
  std::vector<std::uint32_t> bin_items_;  // particle indices, ascending within a bin
  std::vector<std::array<double, 8>> weight_;
  std::vector<std::array<std::uint32_t, 8>> corner_cell_;
  // locate()'s per-particle results in particle order, kept between calls (no allocation).
  std::vector<std::array<int, 3>> scratch_base_;
  std::vector<std::array<double, 8>> scratch_weight_;
  std::vector<Index> scratch_bin_;
  // Buffers of the deposits and interpolations, kept between calls: a fresh vector is zero-filled
  // by one thread, which on the default fluidized bed's 6,000 cells was a fifth of a deposit on
  // 2 threads. A call reads only entries it wrote first. Mutable, so the const calls of one
  // kernel must not run concurrently (class comment). About 64 B per cell and per particle.
  mutable std::vector<double> work_q_;       // per particle, nc values each, particle order
  mutable std::vector<double> work_binned_;  // the same in bin order
  mutable std::vector<double> work_in_;      // per cell, nc values each: filter input (scratch)
  mutable std::vector<double> work_out_;     // per cell: filter output
  // Per z plane, from locate(): a particle has a trilinear corner there (occupied_), or within the
  // filter's reach of one (reach_). A bed fills a fraction of its column, and the filter passes,
  // the bulk of the exchange's cost, need only these planes.
  std::vector<std::uint8_t> occupied_, reach_;
  std::size_t unmapped_ = 0;
  Index first_unmapped_ = -1;
};

}  // namespace lbdem::coupling

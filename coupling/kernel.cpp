#include "coupling/kernel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lbdem::coupling {

// The vector fields are sampled as flat arrays of doubles (x, y, z per entry).
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three contiguous doubles");

namespace {

// Discrete variance sum k^2 g(k) / sum g(k) of the triweight g(k) = (1 - (k/R)^2)^3, |k| < R.
double triweight_variance(double r) {
  double s0 = 1.0, s2 = 0.0;
  for (int k = 1; k < r; ++k) {
    const double u = 1.0 - (k / r) * (k / r);
    const double g = u * u * u;
    s0 += 2.0 * g;
    s2 += 2.0 * double(k) * k * g;
  }
  return s2 / s0;
}

// The cell a tap at coordinate j (possibly outside 0..n-1) reads on a non-periodic axis: the
// faces at -1/2 and n - 1/2 are mirrors, so j is reflected until it lies in the box (a kernel
// wider than the box reflects more than once). The images of cell i are i + 2 n m and
// -1 - i + 2 n m, so the mirrored filter is symmetric and sums to 1 along rows and columns.
int fold(int j, int n) {
  const int p = 2 * n;
  j = ((j % p) + p) % p;
  return j < n ? j : p - 1 - j;
}

// A plane mask for ParticleKernel::filter: null (every plane) before the first locate().
const std::uint8_t* planes(const std::vector<std::uint8_t>& mask) {
  return mask.empty() ? nullptr : mask.data();
}

void require_size(std::size_t got, std::size_t want, const char* what) {
  if (got != want)
    throw std::invalid_argument(std::string("ParticleKernel: ") + what + " has " +
                                std::to_string(got) + " entries, expected " + std::to_string(want));
}

// Sizes a reused buffer to at least n entries. It only grows: the exchange alternates between
// fields of 1, 3 and 4 components, and shrinking and growing again would zero-fill the regrown
// part on one thread at every call. So a buffer may be longer than a call needs: the passes
// index it by cell and component, and only what a call wrote first is read.
void grow(std::vector<double>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}

}  // namespace

ParticleKernel::ParticleKernel(const lbm::Grid& grid, const lbm::LatticeFrame& frame, double width,
                               std::span<const std::uint8_t> solid,
                               const std::optional<ParticleBox>& box)
    : grid_(grid), frame_(frame), width_(width), dx_(frame.dx) {
  // Below sigma = dx the filter has fewer than 5 taps, and the trilinear step's share of the
  // variance, f (1 - f) (0 to 1/4 cell^2 with the position in the cell), would dominate the width.
  if (!(width >= dx_ && std::isfinite(width)))
    throw std::invalid_argument("kernel width " + std::to_string(width) +
                                " m is below the cell size " + std::to_string(dx_) +
                                " m; use at least one cell (default_kernel_width)");
  // The trilinear step adds f (1 - f) to the variance, 1/6 on average over the cell, so the filter
  // carries the rest. var(R) rises continuously from 0 at R = 1 (one tap) past s2 at 3 s + 3
  // (about R^2 / 9 for large R): bisection to round-off.
  const double s2 = (width / dx_) * (width / dx_) - 1.0 / 6.0;
  double lo = 1.0, hi = 3.0 * std::sqrt(s2) + 3.0;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (triweight_variance(mid) < s2 ? lo : hi) = mid;
  }
  radius_ = hi;
  half_ = int(std::ceil(radius_)) - 1;
  taps_.resize(std::size_t(half_) + 1);
  double sum = 0;
  for (int k = 0; k <= half_; ++k) {
    const double u = 1.0 - (k / radius_) * (k / radius_);
    taps_[std::size_t(k)] = u * u * u;
    sum += (k == 0 ? 1.0 : 2.0) * taps_[std::size_t(k)];
  }
  for (double& g : taps_) g /= sum;

  const auto ncell = std::size_t(grid_.cells());
  if (ncell >= std::size_t(UINT32_MAX))
    throw std::invalid_argument("ParticleKernel: 2^32 cells or more (cell indices are 32-bit)");
  gas_.assign(ncell, 1);
  if (!solid.empty()) {
    require_size(solid.size(), ncell, "solid mask");
    for (std::size_t c = 0; c < ncell; ++c) gas_[c] = solid[c] ? 0 : 1;
  }
  // Per axis and coordinate: the cells of the particles' box a grid cell stands for. The outer
  // cell of a non-periodic axis reaches to the box's face, beyond its own face where the box is
  // larger, short of it where the grid sticks out.
  std::array<std::vector<double>, 3> along;
  for (int a = 0; a < 3; ++a) {
    const int n = grid_.extent(a);
    auto& v = along[std::size_t(a)];
    v.assign(std::size_t(n), 1.0);
    if (!box || grid_.periodic(a)) continue;
    // Extensions beyond the grid's faces [cells]; within 1e-9 of a cell is the face itself (the
    // tolerance of scenarios/common/fluid_config.cpp for an edge of whole cells).
    double ext[2] = {(frame_.origin[a] - box->lo[a]) / dx_,
                     (box->hi[a] - (frame_.origin[a] + n * dx_)) / dx_};
    for (double& e : ext) {
      if (std::abs(e) <= 1e-9) e = 0;
      if (!(std::abs(e) < 1))
        throw std::invalid_argument(
            "ParticleKernel: a face of the particles' box lies a cell or more from the grid's");
    }
    v.front() += ext[0];
    v.back() += ext[1];
    if (!(v.front() > 0 && v.back() > 0))
      throw std::invalid_argument("ParticleKernel: the particles' box is empty along an axis");
  }
  volume_.assign(ncell, 0.0);
  for (int z = 0; z < grid_.nz(); ++z)
    for (int y = 0; y < grid_.ny(); ++y)
      for (int x = 0; x < grid_.nx(); ++x) {
        const auto c = std::size_t(cell(x, y, z));
        if (gas_[c])
          volume_[c] =
              along[0][std::size_t(x)] * along[1][std::size_t(y)] * along[2][std::size_t(z)];
      }
  for (int a = 0; a < 3; ++a) {
    const int n = grid_.extent(a);
    auto& list = tap_list_[std::size_t(a)];
    list.assign(std::size_t(n), {});
    for (int i = 0; i < n; ++i)
      for (int k = -half_; k <= half_; ++k) {
        // A kernel wider than the box wraps, or reflects, more than once.
        const int j = grid_.periodic(a) ? (((i + k) % n) + n) % n : fold(i + k, n);
        list[std::size_t(i)].push_back({j, taps_[std::size_t(std::abs(k))]});
      }
  }
  balance();
}

void ParticleKernel::balance() {
  const auto ncell = std::size_t(grid_.cells());
  // The mirrored filter G is symmetric with unit row and column sums: on a box without solid
  // cells, whose cells all stand for one cell of it, d = 1 (post = 1, pre = 1 / sum of the taps).
  // Solid cells take rows and columns out of it, and outer cells of a grid centred on a box of
  // other size weigh a != 1; d then solves d (G m d) = 1 on the gas cells (Sinkhorn-Knopp
  // balancing by Knight's iteration d <- sqrt(d / G m d), P. A. Knight 2008, SIAM J. Matrix Anal.
  // Appl. 30, 261: symmetric for m of 0 and 1, and with e = sqrt(m) d the symmetric balance of
  // sqrt(m) G sqrt(m) to row sums m otherwise), which converges linearly, about a decade per 3
  // iterations for these kernels.
  std::vector<double> d(ncell, 1.0), in, gd;
  const bool uniform = std::all_of(volume_.begin(), volume_.end(), [](double m) { return m == 1; });
  balance_error_ = 0;
  for (int it = 0;; ++it) {
    in.resize(ncell);
    const bool par = grid_.cells() >= kMinParallelCells;
#pragma omp parallel for schedule(static) if (par)
    for (std::size_t c = 0; c < ncell; ++c) in[c] = volume_[c] * d[c];
    filter(in, gd, 1);
    double err = 0;
#pragma omp parallel for schedule(static) reduction(max : err) if (par)
    for (std::size_t c = 0; c < ncell; ++c)
      if (gas_[c]) err = std::max(err, std::abs(d[c] * gd[c] - 1.0));
    balance_error_ = err;
    if (uniform || err <= kBalanceTolerance || it == kBalanceIterations) break;
#pragma omp parallel for schedule(static) if (par)
    for (std::size_t c = 0; c < ncell; ++c)
      if (gas_[c]) d[c] = std::sqrt(d[c] / gd[c]);
  }
  // pre = 1 / (G m d) normalises every column exactly (each source cell's share sums to 1 to
  // round-off, whether or not the balance converged); on the gas cells it equals d to the
  // balance error, so that the rows sum to 1 as well.
  pre_.resize(ncell);
  post_.resize(ncell);
  for (std::size_t c = 0; c < ncell; ++c) {
    pre_[c] = gd[c] > 0 ? 1.0 / gd[c] : 0.0;
    post_[c] = volume_[c] * d[c];
  }
}

std::vector<std::uint8_t> ParticleKernel::solid_mask(const lbm::FlagField& flags) {
  const lbm::Grid& g = flags.grid();
  std::vector<std::uint8_t> solid(std::size_t(g.cells()));
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x)
        solid[std::size_t(g.compact_index(x, y, z))] = flags.at(x, y, z) != lbm::kFluid;
  return solid;
}

std::vector<int> ParticleKernel::listed_planes(const std::uint8_t* planes, bool active) const {
  std::vector<int> list;
  for (int z = 0; z < grid_.nz(); ++z)
    if ((!planes || planes[z]) == active) list.push_back(z);
  return list;
}

void ParticleKernel::zero_planes(const std::vector<int>& list, std::vector<double>& out,
                                 int nc) const {
  const auto plane = std::size_t(grid_.nx()) * std::size_t(grid_.ny()) * std::size_t(nc);
  const int n = int(list.size());
#pragma omp for schedule(static) nowait
  for (int i = 0; i < n; ++i) {
    const auto z = std::size_t(list[std::size_t(i)]);
    std::fill(out.begin() + std::ptrdiff_t(z * plane),
              out.begin() + std::ptrdiff_t((z + 1) * plane), 0.0);
  }
}

void ParticleKernel::filter_axis(const std::vector<double>& in, std::vector<double>& out, int axis,
                                 const PlaneLists& planes, int nc) const {
  const int nx = grid_.nx(), ny = grid_.ny(), h = half_;
  zero_planes(planes.off, out, nc);
  if (axis != 0) return filter_planes(in, out, axis, planes.on, nc);
  const std::vector<int>& active = planes.on;
  const bool wrap_x = grid_.periodic(0);
  const int na = int(active.size());
  const auto len = std::size_t(nx) * std::size_t(nc);  // a row's values
  const auto halo = std::size_t(h) * std::size_t(nc);
#pragma omp for collapse(2) schedule(static)
  for (int a = 0; a < na; ++a)
    for (int y = 0; y < ny; ++y) {
      const int z = active[std::size_t(a)];
      const std::size_t at = std::size_t(cell(0, y, z)) * std::size_t(nc);
      double* o = out.data() + at;
      // The row with H cells of halo on each side (wrapped, or mirrored at a non-periodic face,
      // as the tap list reads them), so that each tap is one contiguous, vectorisable sweep over
      // all components; taps are added in the same order, k = -H..H.
      thread_local std::vector<double> pad;
      pad.resize(len + 2 * halo);
      const double* row = in.data() + at;
      std::copy(row, row + len, pad.begin() + std::ptrdiff_t(halo));
      for (int i = 1; i <= h; ++i)
        for (int m = 0; m < nc; ++m) {
          const int jl = wrap_x ? ((-i % nx) + nx) % nx : fold(-i, nx);
          const int jh = wrap_x ? (nx - 1 + i) % nx : fold(nx - 1 + i, nx);
          const double lo = row[std::size_t(jl) * std::size_t(nc) + std::size_t(m)];
          const double hi = row[std::size_t(jh) * std::size_t(nc) + std::size_t(m)];
          pad[std::size_t(h - i) * std::size_t(nc) + std::size_t(m)] = lo;
          pad[std::size_t(nx - 1 + h + i) * std::size_t(nc) + std::size_t(m)] = hi;
        }
      for (std::size_t x = 0; x < len; ++x) o[x] = 0;
      for (int k = -h; k <= h; ++k) {
        const double g = taps_[std::size_t(std::abs(k))];
        const double* src = pad.data() + std::ptrdiff_t(h + k) * nc;
        for (std::size_t x = 0; x < len; ++x) o[x] += g * src[x];
      }
    }
}

// The y and z passes a plane at a time: for each offset k = -H..H, in tap order, the output rows
// whose neighbour row lies in the box (or wraps, on a periodic axis) form at most two contiguous
// runs of memory, long vectorisable sweeps even where the rows are short (a 4 mm bed is 10-20
// cells wide). Each cell still adds its taps in the order of its tap list.
void ParticleKernel::filter_planes(const std::vector<double>& in, std::vector<double>& out,
                                   int axis, const std::vector<int>& active, int nc) const {
  const int nx = grid_.nx(), ny = grid_.ny(), h = half_;
  const auto row = std::size_t(nx) * std::size_t(nc);
  const auto plane = row * std::size_t(ny);
  auto axpy = [](double* o, const double* src, std::size_t n, double g) {
    for (std::size_t i = 0; i < n; ++i) o[i] += g * src[i];
  };
  const int na = int(active.size());
#pragma omp for schedule(static)
  for (int a = 0; a < na; ++a) {
    const int z = active[std::size_t(a)];
    double* o = out.data() + std::size_t(z) * plane;
    std::fill(o, o + plane, 0.0);
    if (axis == 2) {
      for (const Tap& t : tap_list_[2][std::size_t(z)])
        axpy(o, in.data() + std::size_t(t.j) * plane, plane, t.g);
      continue;
    }
    const double* p = in.data() + std::size_t(z) * plane;
    for (int k = -h; k <= h; ++k) {
      const double g = taps_[std::size_t(std::abs(k))];
      if (grid_.periodic(1)) {
        // Rows y < ny - s read row y + s, the others row y + s - ny (s = k mod ny).
        const int s = ((k % ny) + ny) % ny;
        axpy(o, p + std::size_t(s) * row, std::size_t(ny - s) * row, g);
        axpy(o + std::size_t(ny - s) * row, p, std::size_t(s) * row, g);
      } else {
        // The rows whose neighbour lies in the box in one run, the others a row at a time from
        // their mirror images (each cell still takes one term per k).
        const int y0 = std::max(0, -k), y1 = std::min(ny, ny - k);
        if (y0 < y1)
          axpy(o + std::size_t(y0) * row, p + std::size_t(y0 + k) * row, std::size_t(y1 - y0) * row,
               g);
        for (int y = 0; y < ny; ++y)
          if (y < y0 || y >= y1)
            axpy(o + std::size_t(y) * row, p + std::size_t(fold(y + k, ny)) * row, row, g);
      }
    }
  }
}

void ParticleKernel::filter(std::vector<double>& in, std::vector<double>& out, int nc,
                            const std::uint8_t* xy, const std::uint8_t* z) const {
  grow(out, in.size());
  // The planes to filter, listed so that the threads share them evenly (a bed fills the lower
  // planes of its column, which a static split over all planes would give one thread); the
  // others read 0. The three passes share one parallel region (the barrier at the end of each
  // pass orders them): on the default fluidized bed's 6,000 cells, to 0.2 s on 2 threads, the
  // exchange took 3.41 s with a region per loop and 3.12-3.22 s with this one.
  const PlaneLists on_xy{listed_planes(xy, true), listed_planes(xy, false)};
  const PlaneLists on_z{listed_planes(z, true), listed_planes(z, false)};
#pragma omp parallel if (grid_.cells() >= kMinParallelCells)
  {
    filter_axis(in, out, 0, on_xy, nc);
    filter_axis(out, in, 1, on_xy, nc);
    filter_axis(in, out, 2, on_z, nc);
  }
}

void ParticleKernel::locate(std::span<const Vec3> positions) {
  const std::size_t np = positions.size();
  if (np > std::size_t(UINT32_MAX))
    throw std::invalid_argument("ParticleKernel: too many particles");
  std::vector<std::array<int, 3>>& base = scratch_base_;
  std::vector<std::array<double, 8>>& weight = scratch_weight_;
  std::vector<Index>& bin = scratch_bin_;
  base.resize(np);
  weight.resize(np);
  bin.resize(np);
  for (int a = 0; a < 3; ++a) bins_[std::size_t(a)] = grid_.extent(a) + (grid_.periodic(a) ? 0 : 1);

  std::size_t first_bad = np;  // the lowest particle with a non-finite position
#pragma omp parallel for schedule(static) reduction(min \
                                                    : first_bad) if (np >= kMinParallelParticles)
  for (std::size_t p = 0; p < np; ++p) {
    if (!positions[p].allFinite()) {
      first_bad = std::min(first_bad, p);
      bin[p] = 0;  // unused: the call throws below
      continue;
    }
    const Vec3 xl = frame_.to_lattice(positions[p]);
    double f[3];
    bool ok[3][2];
    std::array<int, 3> lo;
    Index b = 0, stride = 1;
    for (int a = 0; a < 3; ++a) {
      const int n = grid_.extent(a);
      double t = xl[a];
      if (grid_.periodic(a)) {
        t -= n * std::floor(t / n);
        if (!(t < n)) t = 0;  // t = n by round-off of a tiny negative coordinate
      } else {
        t = std::clamp(t, -0.5, n - 0.5);  // outside the box: at the face
      }
      const int i = int(std::floor(t));
      f[a] = t - i;
      lo[std::size_t(a)] = i;
      ok[a][0] = grid_.periodic(a) || i >= 0;
      ok[a][1] = grid_.periodic(a) || i + 1 < n;
      b += (i + (grid_.periodic(a) ? 0 : 1)) * stride;
      stride *= bins_[std::size_t(a)];
    }
    base[p] = lo;
    bin[p] = b;
    std::array<double, 8>& w = weight[p];
    double sum = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const int c[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
      w[std::size_t(corner)] = 0;
      if (!(ok[0][c[0]] && ok[1][c[1]] && ok[2][c[2]])) continue;
      int q[3];
      for (int a = 0; a < 3; ++a) {
        q[a] = lo[std::size_t(a)] + c[a];
        if (q[a] == grid_.extent(a)) q[a] = 0;  // periodic wrap (a non-periodic n is not ok)
      }
      if (pre_[std::size_t(cell(q[0], q[1], q[2]))] == 0) continue;  // no gas within reach
      const double wc =
          (c[0] ? f[0] : 1 - f[0]) * (c[1] ? f[1] : 1 - f[1]) * (c[2] ? f[2] : 1 - f[2]);
      w[std::size_t(corner)] = wc;
      sum += wc;
    }
    if (sum > 0)
      for (double& wc : w) wc /= sum;
  }

  if (first_bad < np)
    throw std::invalid_argument("ParticleKernel::locate: particle " + std::to_string(first_bad) +
                                " has a non-finite position");

  // Counting sort by bin: stable, so each bin lists its particles by index and the deposits below
  // add them in an order fixed by the input alone. Only the slot indices are found serially; the
  // particle data are then gathered into bin order in parallel, which makes the deposits and
  // samples read memory contiguously.
  const Index nbins = Index(bins_[0]) * bins_[1] * bins_[2];
  bin_start_.assign(std::size_t(nbins) + 1, 0);
  for (std::size_t p = 0; p < np; ++p) ++bin_start_[std::size_t(bin[p]) + 1];
  for (Index k = 0; k < nbins; ++k) bin_start_[std::size_t(k) + 1] += bin_start_[std::size_t(k)];
  bin_items_.resize(np);
  weight_.resize(np);
  corner_cell_.resize(np);
  {
    std::vector<Index> fill(bin_start_.begin(), bin_start_.end() - 1);
    for (std::size_t p = 0; p < np; ++p)
      bin_items_[std::size_t(fill[std::size_t(bin[p])]++)] = std::uint32_t(p);
  }
  std::size_t unmapped = 0, first_unmapped = np;
#pragma omp parallel for schedule(static) reduction(+ : unmapped) reduction(min : first_unmapped) \
    if (np >= kMinParallelParticles)
  for (std::size_t k = 0; k < np; ++k) {
    const std::size_t p = bin_items_[k];
    weight_[k] = weight[p];
    bool any = false;
    for (int corner = 0; corner < 8; ++corner) {
      std::uint32_t c = 0;
      if (weight[p][std::size_t(corner)] != 0) {  // the readers skip w == 0
        any = true;
        int q[3];
        for (int a = 0; a < 3; ++a) {
          q[a] = base[p][std::size_t(a)] + ((corner >> a) & 1);
          if (q[a] == grid_.extent(a)) q[a] = 0;
        }
        c = std::uint32_t(cell(q[0], q[1], q[2]));
      }
      corner_cell_[k][std::size_t(corner)] = c;
    }
    if (!any) ++unmapped, first_unmapped = std::min(first_unmapped, p);
  }
  unmapped_ = unmapped;
  first_unmapped_ = unmapped ? Index(first_unmapped) : -1;

  // Planes the particles touch: from the bins, whose z coordinate is the slowest (bin plane b
  // holds the particles whose lower trilinear cell is b, or b - 1 on a non-periodic axis), each
  // touching its lower plane and the one above.
  const int nz = grid_.nz();
  const Index per_plane = Index(bins_[0]) * bins_[1];
  occupied_.assign(std::size_t(nz), 0);
  for (int b = 0; b < bins_[2]; ++b) {
    if (bin_start_[std::size_t((b + 1) * per_plane)] == bin_start_[std::size_t(b * per_plane)])
      continue;
    const int lower = grid_.periodic(2) ? b : b - 1;
    for (int z : {lower, lower + 1}) {
      const int q = grid_.periodic(2) ? z % nz : z;
      if (q >= 0 && q < nz) occupied_[std::size_t(q)] = 1;
    }
  }
  reach_.assign(std::size_t(nz), 0);
  for (int z = 0; z < nz; ++z)
    for (const Tap& t : tap_list_[2][std::size_t(z)])
      if (occupied_[std::size_t(t.j)]) reach_[std::size_t(z)] = 1;
}

template <int NC>
void ParticleKernel::gather_sources(const std::vector<double>& qs, std::vector<double>& src) const {
  const auto ncell = std::size_t(grid_.cells());
  if (bin_start_.empty()) return src.assign(ncell * NC, 0.0);  // before the first locate()
  grow(src, ncell * NC);                                       // every plane is cleared below
  // Each cell receives its terms in the order of a per-cell gather over its 8 bins: corner 0
  // first, each bin's particles by index. Cell plane z is written by one thread only, from two
  // bin planes: corners 0-3 from the particles whose lower trilinear plane is z, corners 4-7
  // from those whose lower plane is z - 1 (wrapped). So the planes run in parallel without races
  // or atomics, in one parallel region, at a cost of 8 per particle; the same thread clears the
  // plane first and scales it by 1/Z last.
  const int nz = grid_.nz();
  const bool wrap = grid_.periodic(2);
  const Index per_plane = Index(bins_[0]) * bins_[1];
  const auto plane = std::size_t(grid_.nx()) * std::size_t(grid_.ny());
  // Bin plane of the particles whose lower trilinear plane is i (-1 allowed on a non-periodic
  // axis).
  const auto bin_plane = [&](int i) { return wrap ? (i + nz) % nz : i + 1; };
  // Dynamic: a bed fills the lower planes only, which a static split would give one thread.
#pragma omp parallel for schedule(dynamic, 1) if (particle_count() >= kMinParallelParticles || \
                                                  grid_.cells() >= kMinParallelCells)
  for (int z = 0; z < nz; ++z) {
    double* s = src.data() + std::size_t(z) * plane * NC;
    std::fill(s, s + plane * NC, 0.0);
    for (int corner = 0; corner < 8; ++corner) {
      const int b = bin_plane(corner < 4 ? z : z - 1);
      for (Index k = bin_start_[std::size_t(b * per_plane)];
           k < bin_start_[std::size_t((b + 1) * per_plane)]; ++k) {
        const double w = weight_[std::size_t(k)][std::size_t(corner)];
        if (w == 0) continue;  // also every corner outside a non-periodic box
        const std::size_t c = corner_cell_[std::size_t(k)][std::size_t(corner)];
        for (int a = 0; a < NC; ++a)
          src[c * NC + std::size_t(a)] += w * qs[std::size_t(k) * NC + std::size_t(a)];
      }
    }
    const double* iz = pre_.data() + std::size_t(z) * plane;
    for (std::size_t c = 0; c < plane; ++c)
      for (int a = 0; a < NC; ++a) s[c * NC + std::size_t(a)] *= iz[c];
  }
}

template <int NC>
void ParticleKernel::sample(const double* v, double* out) const {
  const std::size_t np = particle_count();
#pragma omp parallel for schedule(static) if (np >= kMinParallelParticles)
  for (std::size_t k = 0; k < np; ++k) {
    double s[NC] = {};
    for (int corner = 0; corner < 8; ++corner) {
      const double w = weight_[k][std::size_t(corner)];
      if (w == 0) continue;  // also every corner outside a non-periodic box
      const std::size_t c = corner_cell_[k][std::size_t(corner)];
      for (int a = 0; a < NC; ++a) s[a] += w * v[c * NC + std::size_t(a)];
    }
    for (int a = 0; a < NC; ++a) out[std::size_t(bin_items_[k]) * NC + std::size_t(a)] = s[a];
  }
}

template <int NC>
void ParticleKernel::sample_local(const double* field, double* out) const {
  const std::size_t np = particle_count();
#pragma omp parallel for schedule(static) if (np >= kMinParallelParticles)
  for (std::size_t k = 0; k < np; ++k) {
    double s[NC] = {}, sw = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const double w = weight_[k][std::size_t(corner)];
      if (w == 0) continue;
      const std::size_t c = corner_cell_[k][std::size_t(corner)];
      for (int a = 0; a < NC; ++a) s[a] += w * field[c * NC + std::size_t(a)];
      sw += w;
    }
    const double inv = sw > 0 ? 1.0 / sw : 0.0;
    for (int a = 0; a < NC; ++a) out[std::size_t(bin_items_[k]) * NC + std::size_t(a)] = s[a] * inv;
  }
}

void ParticleKernel::interpolate_local(std::span<const double> field,
                                       std::vector<double>& out) const {
  require_size(field.size(), std::size_t(grid_.cells()), "interpolated field");
  out.resize(particle_count());
  sample_local<1>(field.data(), out.data());
}

void ParticleKernel::interpolate_local(std::span<const Vec3> field, std::vector<Vec3>& out) const {
  require_size(field.size(), std::size_t(grid_.cells()), "interpolated field");
  out.resize(particle_count());
  // Cast, not ->data(): with no particles out.data() is null (a feed that has not started yet).
  sample_local<3>(reinterpret_cast<const double*>(field.data()),
                  reinterpret_cast<double*>(out.data()));
}

void ParticleKernel::smooth(std::vector<double>& in, std::vector<double>& v, int nc) const {
  const auto ncell = std::size_t(grid_.cells());
  const auto m = std::size_t(nc);
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < ncell;
       ++c)  // solid cells may hold anything (NaN too): set, not scaled
    for (std::size_t a = 0; a < m; ++a) in[c * m + a] = gas_[c] ? post_[c] * in[c * m + a] : 0.0;
  filter(in, v, nc, planes(reach_), planes(occupied_));
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < ncell; ++c)
    for (std::size_t a = 0; a < m; ++a) v[c * m + a] *= pre_[c];
}

template <int NC>
const std::vector<double>& ParticleKernel::deposit_components(const double* qs) const {
  const std::size_t np = particle_count();
  std::vector<double>& binned = work_binned_;
  grow(binned, NC * np);
#pragma omp parallel for schedule(static) if (np >= kMinParallelParticles)
  for (std::size_t k = 0; k < np; ++k)
    for (int a = 0; a < NC; ++a)
      binned[k * NC + std::size_t(a)] = qs[std::size_t(bin_items_[k]) * NC + std::size_t(a)];
  gather_sources<NC>(binned, work_in_);
  filter(work_in_, work_out_, NC, planes(occupied_), planes(reach_));
  return work_out_;
}

void ParticleKernel::deposit(std::span<const double> q, std::vector<double>& out) const {
  require_size(q.size(), particle_count(), "deposit input");
  const std::vector<double>& dep = deposit_components<1>(q.data());
  out.resize(std::size_t(grid_.cells()));
  const double inv_v = 1.0 / cell_volume();
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = post_[c] * dep[c] * inv_v;
}

void ParticleKernel::deposit(std::span<const Vec3> q, std::vector<Vec3>& out) const {
  require_size(q.size(), particle_count(), "deposit input");
  const std::vector<double>& dep = deposit_components<3>(reinterpret_cast<const double*>(q.data()));
  const auto ncell = std::size_t(grid_.cells());
  out.resize(ncell);
  const double inv_v = 1.0 / cell_volume();
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < ncell; ++c)
    for (int a = 0; a < 3; ++a) out[c][a] = post_[c] * dep[3 * c + std::size_t(a)] * inv_v;
}

void ParticleKernel::deposit(std::span<const double> q, std::span<const Vec3> v,
                             std::vector<double>& out_q, std::vector<Vec3>& out_v) const {
  require_size(q.size(), particle_count(), "deposit input");
  require_size(v.size(), particle_count(), "deposit input");
  std::vector<double>& qs = work_q_;
  grow(qs, 4 * q.size());
#pragma omp parallel for schedule(static) if (q.size() >= kMinParallelParticles)
  for (std::size_t p = 0; p < q.size(); ++p) {
    qs[4 * p] = q[p];
    for (int a = 0; a < 3; ++a) qs[4 * p + 1 + std::size_t(a)] = v[p][a];
  }
  const std::vector<double>& dep = deposit_components<4>(qs.data());
  const auto ncell = std::size_t(grid_.cells());
  out_q.resize(ncell);
  out_v.resize(ncell);
  const double inv_v = 1.0 / cell_volume();
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < ncell; ++c) {
    out_q[c] = post_[c] * dep[4 * c] * inv_v;
    for (int a = 0; a < 3; ++a) out_v[c][a] = post_[c] * dep[4 * c + 1 + std::size_t(a)] * inv_v;
  }
}

const std::vector<double>& ParticleKernel::smoothed(const double* field, int nc) const {
  const auto n = std::size_t(grid_.cells()) * std::size_t(nc);
  grow(work_in_, n);
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t i = 0; i < n; ++i) work_in_[i] = field[i];
  smooth(work_in_, work_out_, nc);
  return work_out_;
}

// Transpose of deposit(): v(c) = pre(c) sum_c' G(c' - c) post(c') field(c'), then trilinear
// weights.
void ParticleKernel::interpolate(std::span<const double> field, std::vector<double>& out) const {
  require_size(field.size(), std::size_t(grid_.cells()), "interpolated field");
  out.resize(particle_count());
  sample<1>(smoothed(field.data(), 1).data(), out.data());
}

void ParticleKernel::interpolate(std::span<const Vec3> field, std::vector<Vec3>& out) const {
  require_size(field.size(), std::size_t(grid_.cells()), "interpolated field");
  out.resize(particle_count());
  sample<3>(smoothed(reinterpret_cast<const double*>(field.data()), 3).data(),
            reinterpret_cast<double*>(out.data()));
}

void ParticleKernel::interpolate(std::span<const double> field, std::span<const Vec3> vfield,
                                 std::vector<double>& out, std::vector<Vec3>& vout) const {
  const auto ncell = std::size_t(grid_.cells());
  require_size(field.size(), ncell, "interpolated field");
  require_size(vfield.size(), ncell, "interpolated field");
  std::vector<double>& in = work_in_;
  grow(in, 4 * ncell);
#pragma omp parallel for schedule(static) if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < ncell; ++c) {
    in[4 * c] = field[c];
    for (int a = 0; a < 3; ++a) in[4 * c + 1 + std::size_t(a)] = vfield[c][a];
  }
  smooth(in, work_out_, 4);
  const std::size_t np = particle_count();
  std::vector<double>& both = work_q_;
  grow(both, 4 * np);
  sample<4>(work_out_.data(), both.data());
  out.resize(np);
  vout.resize(np);
#pragma omp parallel for schedule(static) if (np >= kMinParallelParticles)
  for (std::size_t p = 0; p < np; ++p) {
    out[p] = both[4 * p];
    vout[p] = Vec3(both[4 * p + 1], both[4 * p + 2], both[4 * p + 3]);
  }
}

PorosityReport ParticleKernel::gas_fraction(std::span<const double> radii, double eps_min,
                                            std::vector<double>& eps) const {
  require_size(radii.size(), particle_count(), "radii");
  if (!(eps_min > 0 && eps_min <= 1))
    throw std::invalid_argument("eps_min must lie in (0, 1], got " + std::to_string(eps_min));
  std::vector<double> vol(radii.size());
#pragma omp parallel for schedule(static) if (radii.size() >= kMinParallelParticles)
  for (std::size_t p = 0; p < radii.size(); ++p) vol[p] = 4.0 / 3.0 * kPi * std::pow(radii[p], 3);
  deposit(vol, eps);  // solid fraction phi
  // Over the cells in parallel: the report's figures are reductions that do not depend on the
  // order (a count, a least index, a least value), so they are the same for any thread count.
  const std::size_t ncell = eps.size();
  Index clipped = 0;
  std::size_t first = ncell;
  double lowest = 1.0;
#pragma omp parallel for schedule(static) reduction(+ : clipped) reduction(min : first, lowest) \
    if (grid_.cells() >= kMinParallelCells)
  for (std::size_t c = 0; c < ncell; ++c) {
    if (!gas_[c]) {
      eps[c] = 1.0;
      continue;
    }
    const double e = 1.0 - eps[c] / volume_[c];  // phi over the part of the box the cell holds
    lowest = std::min(lowest, e);
    if (e < eps_min) {
      ++clipped;
      first = std::min(first, c);
      eps[c] = eps_min;
    } else {
      eps[c] = e;
    }
  }
  PorosityReport r;
  r.lowest = lowest;
  r.clipped = clipped;
  if (clipped) {
    const auto nx = std::size_t(grid_.nx()), ny = std::size_t(grid_.ny());
    r.first = {int(first % nx), int(first / nx % ny), int(first / (nx * ny))};
  }
  return r;
}

void ParticleKernel::pressure_gradient(std::span<const double> p, std::vector<Vec3>& grad,
                                       bool reached_only) const {
  require_size(p.size(), std::size_t(grid_.cells()), "pressure field");
  const int n[3] = {grid_.nx(), grid_.ny(), grid_.nz()};
  grad.resize(p.size());  // every cell is written below
  const std::uint8_t* reached = reached_only ? planes(reach_) : nullptr;  // null: every plane
  const auto plane = std::size_t(n[0]) * std::size_t(n[1]);
  // Dynamic: the reached planes of a bed are the lower ones, which a static split would give one
  // thread; the others are only cleared.
#pragma omp parallel for schedule(dynamic, 1) if (grid_.cells() >= kMinParallelCells)
  for (int z = 0; z < n[2]; ++z) {
    Vec3* gz = grad.data() + std::size_t(z) * plane;
    std::fill(gz, gz + plane, Vec3::Zero());
    if (reached && !reached[z]) continue;
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const auto c = std::size_t(cell(x, y, z));
        if (!gas_[c]) continue;
        const int at[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) {
          // Neighbours at -1 and +1 along a: wrapped, or absent outside a non-periodic box.
          std::size_t nb[2];
          bool ok[2];
          for (int s = 0; s < 2; ++s) {
            int q[3] = {x, y, z};
            q[a] = grid_.shift(a, at[a], s ? 1 : -1);
            ok[s] = q[a] >= 0 && q[a] < n[a];
            nb[s] = ok[s] ? std::size_t(cell(q[0], q[1], q[2])) : 0;
            ok[s] = ok[s] && gas_[nb[s]];
          }
          if (ok[0] && ok[1])
            grad[c][a] = (p[nb[1]] - p[nb[0]]) / (2 * dx_);
          else if (ok[1])
            grad[c][a] = (p[nb[1]] - p[c]) / dx_;
          else if (ok[0])
            grad[c][a] = (p[c] - p[nb[0]]) / dx_;
        }
      }
  }
}

}  // namespace lbdem::coupling

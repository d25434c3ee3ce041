#include "dem/pair_list.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace lbdem::dem {

void PairList::resize(std::size_t n) {
  i.resize(n), j.resize(n);
  history.resize(n);
  rolling.resize(n);
  tally.resize(n);
  record.resize(n);
  state.resize(n);
  // Reused storage (the rebuild swaps two lists) holds an older list's values: every pair is
  // cleared, on all threads (129 B per pair, a memory-bound pass that a rebuild every few steps
  // repeats). i and j are left as they are: build_pairs and the checkpoint overwrite them.
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) {
    history[k] = SpringHistory{};
    rolling[k] = RollingHistory{};
    tally[k] = ContactTally{};
    record[k] = ContactRecord{};
    state[k] = 0;
  }
}

void PairList::build_transpose(std::size_t np) {
  const std::size_t n = size();
  jfirst.resize(np + 1);
  jslot.resize(n);
  j_force.resize(n);
  j_torque.resize(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) j_force[k] = j_torque[k] = Vec3::Zero();
  if (n < kMinParallel) {  // a serial counting sort
    std::fill(jfirst.begin(), jfirst.end(), 0u);
    for (auto pj : j) ++jfirst[pj + 1];
    for (std::size_t p = 0; p < np; ++p) jfirst[p + 1] += jfirst[p];
    j_scratch.assign(jfirst.begin(), jfirst.end() - 1);
    for (std::size_t k = 0; k < n; ++k) jslot[k] = j_scratch[j[k]]++;
    return;
  }
  // A counting sort by j in two levels, each in parallel: the pairs are first distributed
  // (stably, over fixed blocks of pairs) to ranges of 4,096 particles, then each range counts and
  // places its own pairs with counters that stay in cache. Stable throughout: ascending pair index
  // within each j, whatever the number of threads.
  constexpr int kShift = 12;
  const std::size_t nr = (np >> kShift) + 1;
  const std::size_t block = block_size(n), nb = (n + block - 1) / block;
  j_hist.resize(nb * nr + 1);
  j_scratch.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    std::uint32_t* h = j_hist.data() + b * nr;
    std::fill(h, h + nr, 0u);
    for (std::size_t k = b * block; k < std::min(n, (b + 1) * block); ++k) ++h[j[k] >> kShift];
  }
  std::vector<std::uint32_t> range_start(nr + 1);
  std::uint32_t running = 0;  // range-major, block-minor
  for (std::size_t r = 0; r < nr; ++r) {
    range_start[r] = running;
    for (std::size_t b = 0; b < nb; ++b) {
      const std::uint32_t c = j_hist[b * nr + r];
      j_hist[b * nr + r] = running;
      running += c;
    }
  }
  range_start[nr] = running;
#pragma omp parallel for schedule(static)
  for (std::size_t b = 0; b < nb; ++b) {
    std::uint32_t* h = j_hist.data() + b * nr;
    for (std::size_t k = b * block; k < std::min(n, (b + 1) * block); ++k)
      j_scratch[h[j[k] >> kShift]++] = static_cast<std::uint32_t>(k);
  }
#pragma omp parallel
  {
    std::vector<std::uint32_t> count((std::size_t(1) << kShift) + 1);
#pragma omp for schedule(dynamic, 1)
    for (std::size_t r = 0; r < nr; ++r) {
      const std::size_t p0 = r << kShift, p1 = std::min(np, (r + 1) << kShift);
      const std::uint32_t s0 = range_start[r], s1 = range_start[r + 1];
      std::fill(count.begin(), count.end(), 0u);
      for (std::uint32_t s = s0; s < s1; ++s) ++count[j[j_scratch[s]] - p0 + 1];
      for (std::size_t q = 0; q + p0 < p1; ++q) {
        count[q + 1] += count[q];
        jfirst[p0 + q] = s0 + count[q];
      }
      for (std::uint32_t s = s0; s < s1; ++s) {
        const std::uint32_t k = j_scratch[s];
        jslot[k] = s0 + count[j[k] - p0]++;
      }
    }
  }
  jfirst[np] = static_cast<std::uint32_t>(n);
}

void CellList::build(const std::vector<Vec3>& x, const CellGrid& g) {
  grid = g;
  if (slot.size() < g.cells()) slot.resize(g.cells());  // once per grid size: O(cells)
  const std::size_t n = x.size();
  sorter.sort(n, [&](std::size_t p) { return static_cast<std::uint32_t>(g.cell_of(x[p])); });
  items.resize(n);
  item_cell.resize(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t s = 0; s < n; ++s) items[s] = sorter.index(s), item_cell[s] = sorter.key(s);
  index_cells();
}

void CellList::renumber(const std::vector<std::uint32_t>& inv) {
  constexpr auto kGone = std::numeric_limits<std::uint32_t>::max();
  const std::size_t n = items.size();
  const auto kept = [&](std::size_t s0, std::size_t s1) {
    return static_cast<std::size_t>(
        std::count_if(items.begin() + std::ptrdiff_t(s0), items.begin() + std::ptrdiff_t(s1),
                      [&](std::uint32_t p) { return inv[p] != kGone; }));
  };
  std::size_t removed = 0;
#pragma omp parallel for schedule(static) reduction(+ : removed) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) removed += inv[k] == kGone;
  if (removed == 0) {  // the same cells, particles renamed
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
    for (std::size_t s = 0; s < n; ++s) items[s] = inv[items[s]];
    return;
  }
  std::vector<std::uint32_t> new_items(n), new_cell(n);
  const std::size_t m = blocked_fill(n, kept, [&](std::size_t s0, std::size_t s1, std::size_t o) {
    for (std::size_t s = s0; s < s1; ++s)
      if (inv[items[s]] != kGone) new_items[o] = inv[items[s]], new_cell[o++] = item_cell[s];
  });
  new_items.resize(m), new_cell.resize(m);
  items.swap(new_items);
  item_cell.swap(new_cell);
  index_cells();
}

void CellList::index_cells() {
  const std::size_t n = item_cell.size();
  const auto starts = [&](std::size_t s) { return s == 0 || item_cell[s] != item_cell[s - 1]; };
  cell.resize(n);
  begin.resize(n + 1);
  const std::size_t nc = blocked_fill(
      n,
      [&](std::size_t s0, std::size_t s1) {
        std::size_t c = 0;
        for (std::size_t s = s0; s < s1; ++s) c += starts(s);
        return c;
      },
      [&](std::size_t s0, std::size_t s1, std::size_t o) {
        for (std::size_t s = s0; s < s1; ++s)
          if (starts(s)) {
            cell[o] = item_cell[s], begin[o] = static_cast<std::uint32_t>(s);
            slot[item_cell[s]] = static_cast<std::uint32_t>(o++);
          }
      });
  cell.resize(nc);
  begin.resize(nc + 1);
  begin[nc] = static_cast<std::uint32_t>(n);
}

std::vector<std::uint32_t> spatial_order(const std::vector<Vec3>& x, const CellGrid& g) {
  CellList cl;
  cl.build(x, g);
  return cl.items;
}

namespace {

// Distinct neighbour coordinates of cell coordinate c along one axis (1 to 3 of them).
int axis_neighbours(int c, int n, bool periodic, std::array<int, 3>& out) {
  int k = 0;
  for (int o = -1; o <= 1; ++o) {
    int v = c + o;
    if (periodic) {
      v = (v % n + n) % n;
    } else if (v < 0 || v >= n) {
      continue;
    }
    bool seen = false;
    for (int q = 0; q < k; ++q) seen = seen || out[q] == v;
    if (!seen) out[k++] = v;
  }
  return k;
}

// The candidate ranges of one cell's neighbourhood in CellList::items: per (y, z) neighbour row,
// the x neighbours that are consecutive cells form one range (cells are x-fastest), so an interior
// cell has 9 ranges instead of 27 cells. Each range keeps the largest particle index it holds:
// one whose largest is not above p holds no partner of p (the half list), whatever the order of
// the particles. Found once per cell and reused while the particles of a cell follow each other
// (the spatial sort puts them together).
struct NeighbourRanges {
  std::size_t cell = std::numeric_limits<std::size_t>::max();
  int count = 0;
  std::array<std::uint32_t, 27> k0{}, k1{}, top{};

  void find(std::size_t key, const std::array<int, 3>& c, const Domain& d, const CellList& cl) {
    cell = key;
    count = 0;
    const CellGrid& g = cl.grid;
    std::array<int, 3> nx{}, ny{}, nz{};
    const int kx = axis_neighbours(c[0], g.n[0], d.periodic[0], nx);
    const int ky = axis_neighbours(c[1], g.n[1], d.periodic[1], ny);
    const int kz = axis_neighbours(c[2], g.n[2], d.periodic[2], nz);
    for (int zc = 0; zc < kz; ++zc)
      for (int yc = 0; yc < ky; ++yc)
        for (int a = 0; a < kx;) {
          // The longest run of consecutive x cells from nx[a] (axis_neighbours lists them in
          // ascending order unless a periodic wrap intervenes).
          int b = a + 1;
          while (b < kx && nx[b] == nx[b - 1] + 1) ++b;
          const std::size_t first = g.index(nx[a], ny[yc], nz[zc]);
          const std::size_t last = g.index(nx[b - 1], ny[yc], nz[zc]);
          a = b;
          // The occupied cells of the run are consecutive in the list, their items one range.
          std::uint32_t s0 = UINT32_MAX, s1 = 0, top_index = 0;
          for (std::size_t cc = first; cc <= last; ++cc) {
            const std::uint32_t s = cl.find(cc);
            if (s == UINT32_MAX) continue;
            s0 = std::min(s0, s), s1 = s + 1;
            top_index = std::max(top_index, cl.items[cl.begin[s + 1] - 1]);
          }
          if (s0 == UINT32_MAX) continue;
          const std::uint32_t r0 = cl.begin[s0], r1 = cl.begin[s1];
          k0[std::size_t(count)] = r0;
          k1[std::size_t(count)] = r1;
          top[std::size_t(count)] = top_index;
          ++count;
        }
  }
};

template <class Visit>
void for_neighbours(std::uint32_t p, const std::vector<Vec3>& x, const std::vector<double>& r,
                    const Domain& d, const CellList& cl, NeighbourRanges& nr, double extra,
                    Visit&& visit) {
  const CellGrid& g = cl.grid;
  const std::array<int, 3> c = {g.coord(x[p][0], 0), g.coord(x[p][1], 1), g.coord(x[p][2], 2)};
  const std::size_t key = g.index(c[0], c[1], c[2]);
  if (key != nr.cell) nr.find(key, c, d, cl);
  const bool per = d.any_periodic();
  for (int m = 0; m < nr.count; ++m) {
    if (nr.top[std::size_t(m)] <= p) continue;
    for (std::uint32_t k = nr.k0[std::size_t(m)]; k < nr.k1[std::size_t(m)]; ++k) {
      const std::uint32_t q = cl.items[k];
      if (q <= p) continue;
      Vec3 dx = x[q] - x[p];
      if (per) dx = d.min_image(dx);
      const double cut = r[p] + r[q] + extra;
      if (dx.squaredNorm() < cut * cut) visit(q);
    }
  }
}

}  // namespace

void build_pairs(const std::vector<Vec3>& x, const std::vector<double>& r, const Domain& d,
                 const CellList& cells, double extra, PairList& out) {
  const std::size_t np = x.size();
  // One pass over the neighbours, not build_rows' count-then-fill (which searched twice: 20 % of
  // the default jet mill run, whose fast parcels rebuild every 4 steps): each block of rows
  // collects its partners in a buffer of its own, and the blocks are then copied in order, so the
  // list is the same for any number of threads.
  constexpr std::size_t kBlock = 256;
  const std::size_t nblocks = (np + kBlock - 1) / kBlock;
  std::vector<std::vector<std::uint32_t>> found(nblocks);
  out.first.assign(np + 1, 0);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t b = 0; b < nblocks; ++b) {
    std::vector<std::uint32_t>& v = found[b];
    v.clear();
    NeighbourRanges nr;
    for (std::size_t p = b * kBlock; p < std::min(np, (b + 1) * kBlock); ++p) {
      const std::size_t before = v.size();
      for_neighbours(static_cast<std::uint32_t>(p), x, r, d, cells, nr, extra,
                     [&](std::uint32_t q) { v.push_back(q); });
      // Each particle's partners ascending: carry_over() finds pairs by binary search.
      std::sort(v.begin() + std::ptrdiff_t(before), v.end());
      out.first[p + 1] = static_cast<std::uint32_t>(v.size() - before);
    }
  }
  prefix_sum(out.first);
  out.resize(out.first[np]);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t b = 0; b < nblocks; ++b) {
    const std::size_t p0 = b * kBlock, p1 = std::min(np, (b + 1) * kBlock);
    std::copy(found[b].begin(), found[b].end(), out.j.begin() + out.first[p0]);
    for (std::size_t p = p0; p < p1; ++p)
      std::fill(out.i.begin() + out.first[p], out.i.begin() + out.first[p + 1],
                static_cast<std::uint32_t>(p));
  }
  out.build_transpose(np);
}

void carry_over(const PairList& old, const std::vector<std::uint32_t>& inv, PairList& fresh) {
  constexpr auto kGone = std::numeric_limits<std::uint32_t>::max();
  // Each interacting old pair's state goes to its fresh pair, or nowhere (a partner removed, or
  // beyond the cut-off, which cannot happen while the skin holds: the contact ends there; its
  // dissipated energy is in DemSolver's ledgers already). Distinct old pairs are distinct fresh
  // pairs, so the copies run in parallel without conflicts.
  const std::size_t n = old.size();
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) {
    if (!old.state[k]) continue;
    const std::uint32_t a0 = inv[old.i[k]], b0 = inv[old.j[k]];
    if (a0 == kGone || b0 == kGone) continue;
    const bool flip = b0 < a0;  // history is "i relative to j"
    const std::uint32_t a = flip ? b0 : a0, b = flip ? a0 : b0;
    const auto beg = fresh.j.begin() + fresh.first[a];
    const auto end = fresh.j.begin() + fresh.first[a + 1];
    const auto pos = std::lower_bound(beg, end, b);
    if (pos == end || *pos != b) continue;
    const auto f = static_cast<std::size_t>(pos - fresh.j.begin());
    SpringHistory h = old.history[k];
    RollingHistory hr = old.rolling[k];
    if (flip) h.xi = -h.xi, hr.theta = -hr.theta;
    fresh.history[f] = h;
    fresh.rolling[f] = hr;
    fresh.tally[f] = old.tally[k];
    fresh.record[f] = old.record[k];
    fresh.state[f] = old.state[k];
  }
}

}  // namespace lbdem::dem

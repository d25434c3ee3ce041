#include "dem/pair_list.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace lbdem::dem {

namespace {
// Below this many pairs (or particles) a pass runs on one thread: an OpenMP region costs more
// than the work.
constexpr std::size_t kMinParallel = 4096;
}  // namespace

void PairList::resize(std::size_t n) {
  i.resize(n), j.resize(n);
  history.resize(n);
  tally.resize(n);
  record.resize(n);
  state.resize(n);
  // Reused storage (the rebuild swaps two lists) holds an older list's values: every pair is
  // cleared, on all threads (169 B per pair, a memory-bound pass that a rebuild every few steps
  // repeats). i and j are left as they are: build_pairs and the checkpoint overwrite them.
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) {
    history[k] = ContactHistory{};
    tally[k] = ContactTally{};
    record[k] = ContactRecord{};
    state[k] = 0;
  }
}

void PairList::build_transpose(std::size_t np) {
  jfirst.assign(np + 1, 0);
  for (auto pj : j) ++jfirst[pj + 1];
  for (std::size_t p = 0; p < np; ++p) jfirst[p + 1] += jfirst[p];
  jslot.resize(size());
  std::vector<std::uint32_t> fill(jfirst.begin(), jfirst.end() - 1);
  for (std::size_t k = 0; k < size(); ++k) jslot[k] = fill[j[k]]++;
  j_force.resize(size());
  j_torque.resize(size());
#pragma omp parallel for schedule(static) if (size() >= kMinParallel)
  for (std::size_t k = 0; k < size(); ++k) j_force[k] = j_torque[k] = Vec3::Zero();
}

void CellList::build(const std::vector<Vec3>& x, const CellGrid& g) {
  grid = g;
  const std::size_t nc = g.cells();
  start.assign(nc + 1, 0);
  std::vector<std::uint32_t> cell(x.size());
#pragma omp parallel for schedule(static) if (x.size() >= kMinParallel)
  for (std::size_t p = 0; p < x.size(); ++p) cell[p] = static_cast<std::uint32_t>(g.cell_of(x[p]));
  for (std::size_t p = 0; p < x.size(); ++p) ++start[cell[p] + 1];
  for (std::size_t c = 0; c < nc; ++c) start[c + 1] += start[c];
  items.resize(x.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t p = 0; p < x.size(); ++p) items[fill[cell[p]]++] = static_cast<std::uint32_t>(p);
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
          const std::uint32_t r0 = cl.start[first], r1 = cl.start[last + 1];
          a = b;
          if (r0 == r1) continue;
          std::uint32_t top_index = 0;
          for (std::size_t cc = first; cc <= last; ++cc)
            if (cl.start[cc + 1] > cl.start[cc])
              top_index = std::max(top_index, cl.items[cl.start[cc + 1] - 1]);
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
  for (std::size_t p = 0; p < np; ++p) out.first[p + 1] += out.first[p];
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

void carry_over(const PairList& old, const std::vector<std::uint32_t>& inv, PairList& fresh,
                std::vector<ContactTally>& dropped) {
  constexpr auto kGone = std::numeric_limits<std::uint32_t>::max();
  // Where each old pair's state goes: a fresh pair, nowhere (not interacting), or dropped (a
  // partner removed, or beyond the cut-off, which cannot happen while the skin holds). Distinct
  // old pairs are distinct fresh pairs, so the copies run in parallel without conflicts; the
  // dropped tallies are then listed serially in a fixed order (removed partners by old index,
  // the rest by new (a, b)), the same for any thread count.
  constexpr std::uint32_t kNone = kGone, kRemoved = kGone - 1, kBeyond = kGone - 2;
  const std::size_t n = old.size();
  std::vector<std::uint32_t> dest(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallel)
  for (std::size_t k = 0; k < n; ++k) {
    dest[k] = kNone;
    if (!old.state[k]) continue;
    const std::uint32_t a0 = inv[old.i[k]], b0 = inv[old.j[k]];
    if (a0 == kGone || b0 == kGone) {
      dest[k] = kRemoved;
      continue;
    }
    const bool flip = b0 < a0;  // history is "i relative to j"
    const std::uint32_t a = flip ? b0 : a0, b = flip ? a0 : b0;
    const auto beg = fresh.j.begin() + fresh.first[a];
    const auto end = fresh.j.begin() + fresh.first[a + 1];
    const auto pos = std::lower_bound(beg, end, b);
    if (pos == end || *pos != b) {
      dest[k] = kBeyond;
      continue;
    }
    const auto f = static_cast<std::size_t>(pos - fresh.j.begin());
    dest[k] = static_cast<std::uint32_t>(f);
    ContactHistory h = old.history[k];
    if (flip) h.xi = -h.xi, h.theta = -h.theta;
    fresh.history[f] = h;
    fresh.tally[f] = old.tally[k];
    fresh.record[f] = old.record[k];
    fresh.state[f] = old.state[k];
  }
  struct Beyond {
    std::uint32_t a, b, src;
  };
  std::vector<Beyond> beyond;
  for (std::size_t k = 0; k < n; ++k) {
    if (dest[k] == kRemoved) dropped.push_back(old.tally[k]);
    if (dest[k] == kBeyond) {
      const std::uint32_t a = inv[old.i[k]], b = inv[old.j[k]];
      beyond.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(k)});
    }
  }
  std::sort(beyond.begin(), beyond.end(),
            [](const Beyond& u, const Beyond& v) { return u.a != v.a ? u.a < v.a : u.b < v.b; });
  for (const Beyond& it : beyond) dropped.push_back(old.tally[it.src]);
}

}  // namespace lbdem::dem

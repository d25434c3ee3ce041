#include "dem/pair_list.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace lbdem::dem {

void PairList::resize(std::size_t n) {
  i.resize(n), j.resize(n);
  history.assign(n, ContactHistory{});
  tally.assign(n, ContactTally{});
  state.assign(n, 0);
}

void PairList::build_transpose(std::size_t np) {
  jfirst.assign(np + 1, 0);
  for (auto pj : j) ++jfirst[pj + 1];
  for (std::size_t p = 0; p < np; ++p) jfirst[p + 1] += jfirst[p];
  jslot.resize(size());
  std::vector<std::uint32_t> fill(jfirst.begin(), jfirst.end() - 1);
  for (std::size_t k = 0; k < size(); ++k) jslot[k] = fill[j[k]]++;
  j_force.assign(size(), Vec3::Zero());
  j_torque.assign(size(), Vec3::Zero());
}

void CellList::build(const std::vector<Vec3>& x, const CellGrid& g) {
  grid = g;
  const std::size_t nc = g.cells();
  start.assign(nc + 1, 0);
  std::vector<std::uint32_t> cell(x.size());
  for (std::size_t p = 0; p < x.size(); ++p) {
    cell[p] = static_cast<std::uint32_t>(g.cell_of(x[p]));
    ++start[cell[p] + 1];
  }
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

template <class Visit>
void for_neighbours(std::uint32_t p, const std::vector<Vec3>& x, const std::vector<double>& r,
                    const Domain& d, const CellList& cl, double extra, Visit&& visit) {
  const CellGrid& g = cl.grid;
  std::array<int, 3> nx{}, ny{}, nz{};
  const int kx = axis_neighbours(g.coord(x[p][0], 0), g.n[0], d.periodic[0], nx);
  const int ky = axis_neighbours(g.coord(x[p][1], 1), g.n[1], d.periodic[1], ny);
  const int kz = axis_neighbours(g.coord(x[p][2], 2), g.n[2], d.periodic[2], nz);
  const bool per = d.any_periodic();
  for (int c = 0; c < kz; ++c)
    for (int b = 0; b < ky; ++b)
      for (int a = 0; a < kx; ++a) {
        const std::size_t cell = g.index(nx[a], ny[b], nz[c]);
        const std::uint32_t k0 = cl.start[cell], k1 = cl.start[cell + 1];
        // A cell lists its particles in ascending order (CellList::build), so one whose last is
        // not above p holds no partner of p. In the spatially sorted order that is every cell
        // before p's own: the half stencil, found without assuming the sort.
        if (k0 == k1 || cl.items[k1 - 1] <= p) continue;
        for (std::uint32_t k = k0; k < k1; ++k) {
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
    for (std::size_t p = b * kBlock; p < std::min(np, (b + 1) * kBlock); ++p) {
      const std::size_t before = v.size();
      for_neighbours(static_cast<std::uint32_t>(p), x, r, d, cells, extra,
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
  struct Item {
    std::uint32_t a, b, src;
    bool flip;
  };
  std::vector<Item> items;
  for (std::uint32_t k = 0; k < old.size(); ++k) {
    if (!old.state[k]) continue;
    const std::uint32_t a = inv[old.i[k]], b = inv[old.j[k]];
    if (a == kGone || b == kGone) {
      dropped.push_back(old.tally[k]);
      continue;
    }
    items.push_back(a < b ? Item{a, b, k, false} : Item{b, a, k, true});
  }
  std::sort(items.begin(), items.end(),
            [](const Item& u, const Item& v) { return u.a != v.a ? u.a < v.a : u.b < v.b; });
  for (const Item& it : items) {
    const auto beg = fresh.j.begin() + fresh.first[it.a];
    const auto end = fresh.j.begin() + fresh.first[it.a + 1];
    const auto pos = std::lower_bound(beg, end, it.b);
    if (pos == end || *pos != it.b) {  // beyond the cut-off: cannot happen while the skin holds
      dropped.push_back(old.tally[it.src]);
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(pos - fresh.j.begin());
    ContactHistory h = old.history[it.src];
    if (it.flip) h.xi = -h.xi, h.theta = -h.theta;  // both are "i relative to j"
    fresh.history[k] = h;
    fresh.tally[k] = old.tally[it.src];
    fresh.state[k] = old.state[it.src];
  }
}

}  // namespace lbdem::dem

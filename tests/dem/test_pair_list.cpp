// dem/pair_list.hpp against brute force: the linked-cell search with its merged x ranges must list
// exactly the pairs within r_i + r_j + extra (minimum image on periodic axes) that an O(N^2) loop
// finds, whatever the particle order (not spatially sorted here) and on periodic axes of 2 and 3
// cells, where the neighbour list wraps onto itself. And a list rebuilt into the storage of an
// older one (as DemSolver::rebuild does) equals one built fresh, field by field.
#include <catch2/catch.hpp>

#include "dem/pair_list.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

using namespace lbdem;
using namespace lbdem::dem;

namespace {

std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force(const std::vector<Vec3>& x,
                                                                 const std::vector<double>& r,
                                                                 const Domain& d, double extra) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t p = 0; p < x.size(); ++p)
    for (std::uint32_t q = p + 1; q < x.size(); ++q) {
      const double cut = r[p] + r[q] + extra;
      if (d.min_image(x[q] - x[p]).squaredNorm() < cut * cut) out.emplace_back(p, q);
    }
  return out;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace

TEST_CASE("Pair list: the cell search finds the brute-force pairs, and reused storage equals fresh",
          "[dem]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double r_max = 0.05, extra = 0.02, cell = 2 * r_max + extra;  // 0.12
  // Periodic x of 2 cells, periodic y of 3 cells, walls in z (10 cells) with particles up to a
  // cell beyond both faces (clamped into the edge cells).
  Domain d;
  d.lo = Vec3(0, 0, 0);
  d.hi = Vec3(2 * cell + 1e-3, 3 * cell + 1e-3, 10 * cell);
  d.periodic = {true, true, false};
  const CellGrid grid(d, cell);
  REQUIRE(grid.n == std::array<int, 3>{2, 3, 10});
  auto particles = [&](std::size_t n, std::vector<Vec3>& x, std::vector<double>& r) {
    x.resize(n), r.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = Vec3(d.hi[0] * u(rng), d.hi[1] * u(rng), (d.hi[2] + 2 * cell) * u(rng) - cell);
      r[k] = r_max * (0.5 + 0.5 * u(rng));
    }
  };
  std::vector<Vec3> x;
  std::vector<double> r;
  PairList reused;
  for (std::size_t n : {6000, 4500}) {  // above the sizes where the passes run in parallel
    particles(n, x, r);
    CellList cells;
    cells.build(x, grid);
    PairList fresh;
    build_pairs(x, r, d, cells, extra, fresh);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> listed;
    for (std::size_t k = 0; k < fresh.size(); ++k) listed.emplace_back(fresh.i[k], fresh.j[k]);
    const auto want = brute_force(x, r, d, extra);
    REQUIRE(want.size() > 4096);  // enough pairs for the parallel clearing and transpose
    CHECK(listed == want);        // also sorted by (i, j), as carry_over's search needs

    // Dirty the reused list as a step would, then rebuild into it: every field as fresh.
    for (auto& h : reused.history) h.kt = 1;
    for (auto& h : reused.rolling) h.kr = 1;
    for (auto& t : reused.tally) t.e_dissipated = 1;
    for (auto& c : reused.record) c.max_force = 1;
    for (auto& s : reused.state) s = kTouching;
    for (auto& f : reused.j_force) f = Vec3::Ones();
    build_pairs(x, r, d, cells, extra, reused);
    CHECK(same_bytes(reused.i, fresh.i));
    CHECK(same_bytes(reused.j, fresh.j));
    CHECK(same_bytes(reused.first, fresh.first));
    CHECK(same_bytes(reused.history, fresh.history));
    CHECK(same_bytes(reused.rolling, fresh.rolling));
    CHECK(same_bytes(reused.tally, fresh.tally));
    CHECK(same_bytes(reused.record, fresh.record));
    CHECK(same_bytes(reused.state, fresh.state));
    CHECK(same_bytes(reused.jfirst, fresh.jfirst));
    CHECK(same_bytes(reused.jslot, fresh.jslot));
    CHECK(same_bytes(reused.j_force, fresh.j_force));
    CHECK(same_bytes(reused.j_torque, fresh.j_torque));
  }
}

TEST_CASE("Key sort: stable, as std::stable_sort, for any key range and size", "[dem]") {
  std::mt19937_64 rng(11);
  for (std::size_t n :
       {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(5000), std::size_t(70000)})
    for (std::uint32_t range : {1u, 3u, 300u, 1u << 21, 0xffffffffu}) {
      std::uniform_int_distribution<std::uint32_t> u(0, range - 1);
      std::vector<std::uint32_t> key(n);
      for (auto& k : key) k = u(rng) + (range < 1000 ? 123456u : 0u);  // an offset: lo > 0
      std::vector<std::uint32_t> want(n);
      std::iota(want.begin(), want.end(), 0u);
      std::stable_sort(want.begin(), want.end(),
                       [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
      KeySort ks;
      ks.sort(n, [&](std::size_t k) { return key[k]; });
      bool same = ks.a.size() == n;
      for (std::size_t s = 0; same && s < n; ++s)
        same = ks.index(s) == want[s] && ks.key(s) == key[want[s]];
      CHECK(same);
    }
}

TEST_CASE("Cell list: occupied cells only, renumbered as if rebuilt, transpose as a serial fill",
          "[dem]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // A 100 x 100 x 100 grid (1e6 cells) with few particles: a sparse domain.
  Domain d;
  d.hi = Vec3(1, 1, 1);
  const CellGrid grid(d, 0.01);
  REQUIRE(grid.cells() == 1000000);
  CellList cl;
  for (std::size_t n : {std::size_t(5000), std::size_t(40), std::size_t(6000)}) {
    std::vector<Vec3> x(n);
    // Half the particles in a small corner, so that cells hold several.
    for (std::size_t k = 0; k < n; ++k)
      x[k] = k % 2 ? Vec3(u(rng), u(rng), u(rng)) : Vec3(0.05 * u(rng), 0.05 * u(rng), u(rng));
    cl.build(x, grid);  // reuses the slots of the build before: stale entries must not count
    // Reference: a dense counting sort.
    std::vector<std::uint32_t> start(grid.cells() + 1, 0), items(n);
    for (const Vec3& p : x) ++start[grid.cell_of(p) + 1];
    for (std::size_t c = 0; c < grid.cells(); ++c) start[c + 1] += start[c];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < n; ++k) items[fill[grid.cell_of(x[k])]++] = std::uint32_t(k);
    CHECK(cl.items == items);
    bool cells_ok = true;
    std::size_t occupied = 0;
    for (std::size_t c = 0; c < grid.cells(); ++c) {
      const std::uint32_t s = cl.find(c);
      if (start[c + 1] == start[c]) {
        cells_ok = cells_ok && s == UINT32_MAX;
        continue;
      }
      ++occupied;
      cells_ok = cells_ok && s != UINT32_MAX && cl.begin[s] == start[c] &&
                 cl.begin[s + 1] == start[c + 1] && cl.cell[s] == c;
    }
    CHECK(cells_ok);
    CHECK(occupied == cl.cell.size());

    // Sort by the list and drop every seventh particle: renumbered equals built afresh.
    std::vector<std::uint32_t> order;
    for (std::uint32_t k : cl.items)
      if (k % 7) order.push_back(k);
    std::vector<std::uint32_t> inv(n, UINT32_MAX);
    std::vector<Vec3> y(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      inv[order[k]] = std::uint32_t(k), y[k] = x[order[k]];
    cl.renumber(inv);
    CellList fresh;
    fresh.build(y, grid);
    CHECK(cl.items == fresh.items);
    CHECK(cl.item_cell == fresh.item_cell);
    CHECK(cl.cell == fresh.cell);
    CHECK(cl.begin == fresh.begin);
    bool found_ok = true;
    for (std::uint32_t c : fresh.cell) found_ok = found_ok && cl.find(c) == fresh.find(c);
    CHECK(found_ok);
  }

  // The transpose against the serial fill it replaced.
  PairList pl;
  const std::size_t np = 9000;
  std::uniform_int_distribution<std::uint32_t> pick(0, np - 1);
  for (std::uint32_t p = 0; p < np; ++p)
    for (int m = 0; m < 4; ++m)
      if (const std::uint32_t q = pick(rng); q > p) pl.i.push_back(p), pl.j.push_back(q);
  pl.build_transpose(np + 5);  // particles without pairs at the end
  std::vector<std::uint32_t> jfirst(np + 6, 0), jslot(pl.size());
  for (auto q : pl.j) ++jfirst[q + 1];
  for (std::size_t p = 0; p < np + 5; ++p) jfirst[p + 1] += jfirst[p];
  std::vector<std::uint32_t> fill(jfirst.begin(), jfirst.end() - 1);
  for (std::size_t k = 0; k < pl.size(); ++k) jslot[k] = fill[pl.j[k]]++;
  CHECK(pl.jfirst == jfirst);
  CHECK(pl.jslot == jslot);
}

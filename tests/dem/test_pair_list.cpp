// dem/pair_list.hpp against brute force: the linked-cell search with its merged x ranges must list
// exactly the pairs within r_i + r_j + extra (minimum image on periodic axes) that an O(N^2) loop
// finds, whatever the particle order (not spatially sorted here) and on periodic axes of 2 and 3
// cells, where the neighbour list wraps onto itself. And a list rebuilt into the storage of an
// older one (as DemSolver::rebuild does) equals one built fresh, field by field.
#include <catch2/catch.hpp>

#include "dem/pair_list.hpp"

#include <algorithm>
#include <cstring>
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
    for (auto& t : reused.tally) t.e_sliding = 1;
    for (auto& c : reused.record) c.max_force = 1;
    for (auto& s : reused.state) s = kTouching;
    for (auto& f : reused.j_force) f = Vec3::Ones();
    build_pairs(x, r, d, cells, extra, reused);
    CHECK(same_bytes(reused.i, fresh.i));
    CHECK(same_bytes(reused.j, fresh.j));
    CHECK(same_bytes(reused.first, fresh.first));
    CHECK(same_bytes(reused.history, fresh.history));
    CHECK(same_bytes(reused.tally, fresh.tally));
    CHECK(same_bytes(reused.record, fresh.record));
    CHECK(same_bytes(reused.state, fresh.state));
    CHECK(same_bytes(reused.jfirst, fresh.jfirst));
    CHECK(same_bytes(reused.jslot, fresh.jslot));
    CHECK(same_bytes(reused.j_force, fresh.j_force));
    CHECK(same_bytes(reused.j_torque, fresh.j_torque));
  }
}

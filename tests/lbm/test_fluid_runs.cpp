// lbm/fluid_runs.hpp: the collision pass visits the runs of fluid cells, widened over solid cells
// to whole vectors. Equivalence, exact: once the links are applied, every fluid cell holds bitwise
// what colliding every cell gives, in both AA states, with solid cells inside the box and on the
// periodic x edges (where a row splits into x ranges of their own), for unwidened runs and for
// runs widened to 4 and 16 cells. The widening: every fluid cell in exactly one run, runs inside
// their x range and disjoint, and a run short of whole vectors only where it fills the room
// between its neighbours.
#include <catch2/catch.hpp>

#include "lbm/boundary/bounce_back.hpp"
#include "lbm/collision/bgk.hpp"
#include "lbm/forcing/guo.hpp"
#include "lbm/stream_collide.hpp"

#include <cmath>
#include <vector>

using lbdem::Index;
using namespace lbdem::lbm;

namespace {

// The runs' layout: fluid cells covered once, each run inside one x range, disjoint, and a whole
// number of `lanes` long unless it reaches the range's end and its left neighbour (or the range's
// start). Returns the number of solid cells collided.
long check_runs(const Grid& g, const FlagField& flags, const FluidRuns& runs, int lanes) {
  REQUIRE(runs.first.size() == std::size_t(g.ny() * g.nz() + 1));
  long solid_in_runs = 0, fluid_missed = 0, outside = 0, short_runs = 0, overlaps = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y) {
      const std::size_t r = std::size_t(y) + std::size_t(g.ny()) * std::size_t(z);
      std::vector<int> visits(std::size_t(g.nx()), 0);
      for (std::uint32_t k = runs.first[r]; k < runs.first[r + 1]; ++k) {
        const auto [x0, x1] = runs.run[k];
        for (int x = x0; x < x1; ++x) ++visits[std::size_t(x)];
        for_each_x_range(g, [&](int r0, int r1) {
          if (x0 < r0 || x0 >= r1) return;
          outside += x1 > r1;
          if ((x1 - x0) % lanes == 0) return;
          const bool left_full = x0 == r0 || (k > runs.first[r] && runs.run[k - 1][1] == x0);
          short_runs += !(x1 == r1 && left_full);
        });
      }
      for (int x = 0; x < g.nx(); ++x) {
        const bool fluid = flags.fluid(g.index(x, y, z));
        const int v = visits[std::size_t(x)];
        overlaps += v > 1;
        fluid_missed += fluid && v == 0;
        solid_in_runs += !fluid && v > 0;
      }
    }
  CHECK(fluid_missed == 0);
  CHECK(overlaps == 0);
  CHECK(outside == 0);
  CHECK(short_runs == 0);
  if (lanes == 1) CHECK(solid_in_runs == 0);
  return solid_in_runs;
}

// Six steps of BGK with bounce-back, colliding every cell against colliding the runs; returns the
// number of fluid populations that differ.
long differing_fluid_populations(const Grid& g, const FlagField& flags, const FluidRuns& runs) {
  const auto links = build_links(flags, 1);
  PdfField<double> all(g), only(g);
  for (Index k = 0; k < all.size(); ++k)
    all.data()[k] = only.data()[k] = 0.05 * (1.0 + 0.1 * std::sin(0.37 * double(k)));
  const Bgk op = Bgk::from_tau(0.8);
  AaState s = AaState::natural;
  long differ = 0;
  for (int step = 0; step < 6; ++step) {
    stream_collide(all, s, op, NoForce{});
    stream_collide(only, s, op, NoForce{}, &runs);
    s = after_step(s);
    apply_bounce_back(all, s, links[0]);
    apply_bounce_back(only, s, links[0]);
    for (int z = 0; z < g.nz(); ++z)
      for (int y = 0; y < g.ny(); ++y)
        for (int x = 0; x < g.nx(); ++x) {
          if (!flags.fluid(g.index(x, y, z))) continue;
          const double *a[kQ], *b[kQ];
          read_pointers(all, s, x, y, z, a);
          read_pointers(only, s, x, y, z, b);
          for (int q = 0; q < kQ; ++q) differ += *a[q] != *b[q];
        }
  }
  return differ;
}

}  // namespace

TEST_CASE("LBM: colliding only the fluid runs leaves the fluid as colliding every cell", "[lbm]") {
  const Grid g(11, 7, 6, {true, true, true});
  FlagField flags(g);
  for (int z = 2; z < 5; ++z)
    for (int y = 2; y < 5; ++y)
      for (int x = 4; x < 7; ++x) flags.set(x, y, z, 1);
  flags.set(0, 1, 1, 1);   // first cell of a row: the wrapped range [0, 1)
  flags.set(10, 5, 3, 1);  // last cell of a row: the wrapped range [nx - 1, nx)
  flags.set(5, 0, 0, 1);   // a lone solid cell splitting a row in two runs
  for (const int lanes : {1, 4, 16}) {
    INFO("runs widened to " << lanes << " cells");
    const FluidRuns runs = fluid_runs(g, flags, lanes);
    check_runs(g, flags, runs, lanes);
    CHECK(differing_fluid_populations(g, flags, runs) == 0);
  }
}

TEST_CASE("LBM: runs widened to whole vectors in a cylinder leave the fluid unchanged", "[lbm]") {
  // A chamber like the jet mill's: a cylinder of diameter 37 cells in a closed 37 x 37 x 4 box,
  // whose chords of 9-37 cells leave room to widen only where they are short, and a solid post
  // at its centre that splits the middle rows.
  const Grid g(37, 37, 4, {false, false, false});
  FlagField flags(g);
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) {
        const double rx = x - 18.0, ry = y - 18.0, r2 = rx * rx + ry * ry;
        if (r2 > 18.5 * 18.5 || r2 < 2.5 * 2.5) flags.set(x, y, z, 1);
      }
  for (const int lanes : {1, 4, 16}) {
    INFO("runs widened to " << lanes << " cells");
    const FluidRuns runs = fluid_runs(g, flags, lanes);
    const long solid = check_runs(g, flags, runs, lanes);
    if (lanes > 1) CHECK(solid > 0);  // the widening did happen
    CHECK(differing_fluid_populations(g, flags, runs) == 0);
  }
}

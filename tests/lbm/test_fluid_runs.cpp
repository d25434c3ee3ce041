// lbm/fluid_runs.hpp: the collision pass visits only the runs of fluid cells. Equivalence, exact:
// once the links are applied, every fluid cell holds bitwise what colliding every cell gives, in
// both AA states, with solid cells inside the box and on the periodic x edges (where a row splits
// into x ranges of their own).
#include <catch2/catch.hpp>

#include "lbm/boundary/bounce_back.hpp"
#include "lbm/collision/bgk.hpp"
#include "lbm/forcing/guo.hpp"
#include "lbm/stream_collide.hpp"

#include <cmath>

using lbdem::Index;
using namespace lbdem::lbm;

TEST_CASE("LBM: colliding only the fluid runs leaves the fluid as colliding every cell", "[lbm]") {
  const Grid g(11, 7, 6, {true, true, true});
  FlagField flags(g);
  for (int z = 2; z < 5; ++z)
    for (int y = 2; y < 5; ++y)
      for (int x = 4; x < 7; ++x) flags.set(x, y, z, 1);
  flags.set(0, 1, 1, 1);   // first cell of a row: the wrapped range [0, 1)
  flags.set(10, 5, 3, 1);  // last cell of a row: the wrapped range [nx - 1, nx)
  flags.set(5, 0, 0, 1);   // a lone solid cell splitting a row in two runs

  const FluidRuns runs = fluid_runs(g, flags);
  long fluid = 0, in_runs = 0, solid_in_runs = 0;
  for (int z = 0; z < g.nz(); ++z)
    for (int y = 0; y < g.ny(); ++y)
      for (int x = 0; x < g.nx(); ++x) fluid += flags.fluid(g.index(x, y, z));
  for (std::size_t r = 0; r + 1 < runs.first.size(); ++r)
    for (std::uint32_t k = runs.first[r]; k < runs.first[r + 1]; ++k)
      for (int x = runs.run[k][0]; x < runs.run[k][1]; ++x, ++in_runs)
        solid_in_runs += !flags.fluid(g.index(x, int(r) % g.ny(), int(r) / g.ny()));
  CHECK(runs.first.size() == std::size_t(g.ny() * g.nz() + 1));
  CHECK(in_runs == fluid);
  CHECK(solid_in_runs == 0);

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
  INFO(differ << " fluid populations differ");
  CHECK(differ == 0);
}

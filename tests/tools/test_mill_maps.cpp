// The jet mill's maps and profiles (tools/src/mill_maps.hpp) against hand-computed values on
// constructed samples and a constructed gas field (a rigid vortex with a sink).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "tools/src/mill_maps.hpp"

using namespace lbdem::tools;
using lbdem::Vec3;

TEST_CASE("Jet mill maps: binned means, wall distance and jet regions", "[tools][jet_mill]") {
  // Bins of 1 mm from 0: samples at 0.2 and 0.7 mm fall in bin 0 (mean of 2 and 4 is 3), 1.5 mm
  // in bin 1; 3 mm and -0.1 mm lie outside three bins and are dropped.
  Bins1D b(0.0, 1e-3, 3);
  b.add(0.2e-3, 2), b.add(0.7e-3, 4), b.add(1.5e-3, 10), b.add(3e-3, 99), b.add(-1e-4, 99);
  CHECK(b.mean(0) == 3.0);
  CHECK(b.samples(0) == 2);
  CHECK(b.mean(1) == 10.0);
  CHECK(std::isnan(b.mean(2)));
  CHECK(b.centre(1) == Approx(1.5e-3).epsilon(1e-15));
  // A 2 x 2 map of 1 m bins over [-1, 1)^2: (0.5, -0.5) is bin (1, 0).
  Bins2D m(-1, -1, 1, 2);
  m.add(0.5, -0.5, 6), m.add(0.9, -0.1, 8), m.add(-0.5, 0.5, 1), m.add(1.5, 0, 99);
  CHECK(m.mean(1, 0) == 7.0);
  CHECK(m.samples(1, 0) == 2);
  CHECK(m.mean(0, 1) == 1.0);
  CHECK(std::isnan(m.mean(0, 0)));
  CHECK(m.x(1) == 0.5);
  CHECK(m.y(0) == -0.5);
  // The chamber of radius 25 mm about (1, 2) mm: a point 20 mm out along 3-4-5 is 5 mm from the
  // wall; one beyond the cylinder has a negative distance.
  const MillAxis axis{1e-3, 2e-3, 25e-3};
  CHECK(axis.wall_distance(Vec3(1e-3 + 12e-3, 2e-3 + 16e-3, 0.004)) == Approx(5e-3).epsilon(1e-12));
  CHECK(axis.wall_distance(Vec3(1e-3, 2e-3 + 30e-3, 0)) < 0);
  // A jet from (25, 0) mm pointing along -x (radially in): the region is 10 mm long, 2 mm wide
  // on each side; z does not matter.
  JetRegion j{Vec3(25e-3, 0, 0), Vec3(-1, 0, 0), 2e-3, 10e-3};
  CHECK(j.contains(Vec3(20e-3, 1.9e-3, 0.004)));
  CHECK_FALSE(j.contains(Vec3(20e-3, 2.1e-3, 0)));
  CHECK_FALSE(j.contains(Vec3(14e-3, 0, 0)));  // 11 mm along
  CHECK_FALSE(j.contains(Vec3(26e-3, 0, 0)));  // behind the exit
}

TEST_CASE("Jet mill maps: the gas profile of a rigid vortex with a uniform sink",
          "[tools][jet_mill]") {
  // u = Omega x (-y, x) + s (x, y) / r: u_theta = Omega r exactly, u_r = s everywhere. On 40 x 40 x
  // 2 cells of 1 mm about the axis, ring means of u_theta equal Omega times the mean radius of the
  // ring's cell centres (linear in r), which lies within the bin; u_r equals s to round-off. A
  // solid cell (porosity 0) carrying a huge velocity must not count, and layers outside
  // [z_from, z_to) neither.
  const std::array<int, 3> cells = {40, 40, 2};
  const double dx = 1e-3, omega = 1000, s = -3;
  const Vec3 origin(-19.5e-3, -19.5e-3, 0.5e-3);
  std::vector<double> u(3 * 40 * 40 * 2), eps(40 * 40 * 2, 1.0);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        const std::size_t c = std::size_t((z * 40 + y) * 40 + x);
        const double px = origin.x() + x * dx, py = origin.y() + y * dx, r = std::hypot(px, py);
        u[3 * c] = -omega * py + s * px / r + (z == 1 ? 1e6 : 0);
        u[3 * c + 1] = omega * px + s * py / r;
      }
  eps[5 * 40 + 20] = 0;  // solid: (x 20, y 5) in layer 0
  u[3 * (5 * 40 + 20)] = 1e9;
  const MillAxis axis{0, 0, 20e-3};
  const GasProfile p = gas_profile(u, eps, cells, origin, dx, axis, 2e-3, 0, 1);
  REQUIRE(p.radius.size() == 10);
  double cells_total = 0;
  for (std::size_t k = 0; k < p.radius.size(); ++k) {
    INFO("bin " << k);
    const double lo = p.radius[k] - 1e-3, hi = p.radius[k] + 1e-3;
    CHECK(p.u_theta[k] / omega >= lo);
    CHECK(p.u_theta[k] / omega < hi);
    CHECK(p.u_r[k] == Approx(s).epsilon(1e-12));
    cells_total += p.cells[k];
  }
  // Cells with centres inside r < 20 mm, less the solid one: counted directly.
  double inside = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x)
      if (std::hypot(origin.x() + x * dx, origin.y() + y * dx) < 20e-3) inside += 1;
  CHECK(cells_total == inside - 1);
  // The speed of layer 0: NaN in the solid cell, |u| elsewhere.
  const auto sp = layer_speed(u, eps, cells, 0);
  CHECK(std::isnan(sp[5 * 40 + 20]));
  CHECK(sp[0] == Approx(std::hypot(u[0], u[1])).epsilon(1e-15));
  CHECK_THROWS(layer_speed(u, eps, cells, 2));
}

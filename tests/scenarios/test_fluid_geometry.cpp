// A gas grid on a box whose edges are not whole numbers of cells
// (scenarios/common/fluid_config.cpp): a non-periodic edge L gets n = round(L/dx) cells centred on
// it, so the gas walls lie (n dx - L)/2, at most dx/4, outside or inside the particles' walls; a
// periodic edge must still be whole cells. The start-up banner says where the gas walls lie, and
// fluid.h5 / fluid.xdmf place the cells where the gas has them. The issue's bed: 43.2 x 10 x 124.8
// mm at dx = 2 mm (21.6, 5 and 62.4 cells: rounded up, whole, rounded down).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "core/h5.hpp"
#include "core/log.hpp"
#include "helpers/cli.hpp"
#include "scenarios/common/fluid_config.hpp"
#include "scenarios/common/fluid_output.hpp"

using namespace lbdem;
using namespace lbdem::scenarios;

namespace {

const char* kGas =
    "[fluid]\ndensity = 1.2\nviscosity = 1.8e-5\ndx = 0.002\nmax_speed = 1.0\n"
    "[fluid.faces]\nz_lo = { kind = \"inlet\", velocity = [0.0, 0.0, 0.5] }\n"
    "z_hi = { kind = \"outlet\", pressure = 0.0 }\n";

// The issue's box, its lower corner off the origin so that an origin taken for box.lo shows.
const Vec3 kLo(0.01, -0.02, 0.005), kHi = kLo + Vec3(0.0432, 0.010, 0.1248);

FluidConfig read_issue_box(const std::string& extra = "") {
  const Config c = Config::from_string(std::string(kGas) + extra);
  return read_fluid(c.section("fluid"), kLo, kHi, {false, false, false}, Vec3(0, 0, -9.81));
}

}  // namespace

TEST_CASE("Gas grid on edges that are not whole cells: centred round(L/dx) cells",
          "[scenarios][fluid][input]") {
  const FluidConfig f = read_issue_box();
  // n = round(L/dx): 21.6 -> 22, 5 -> 5, 62.4 -> 62.
  CHECK(f.cells == std::array<int, 3>{22, 5, 62});
  // Centred: the grid is (n dx - L) larger along x (0.8 mm: 0.4 mm beyond each wall), whole along
  // y, 0.8 mm shorter along z (0.4 mm inside each wall).
  const double dx = 0.002;
  CHECK(f.wall_offset(0) == Approx(0.4e-3).epsilon(1e-12));
  CHECK(f.wall_offset(1) == 0);
  CHECK(f.wall_offset(2) == Approx(-0.4e-3).epsilon(1e-12));
  CHECK(f.lo.x() == Approx(kLo.x() - 0.4e-3).epsilon(1e-14));
  CHECK(f.lo.y() == kLo.y());  // exactly: a whole edge keeps the grid on the box
  CHECK(f.lo.z() == Approx(kLo.z() + 0.4e-3).epsilon(1e-14));
  const Vec3 hi = f.hi();
  CHECK(hi.x() == Approx(kHi.x() + 0.4e-3).epsilon(1e-14));
  CHECK(hi.y() == Approx(kHi.y()).epsilon(1e-14));
  CHECK(hi.z() == Approx(kHi.z() - 0.4e-3).epsilon(1e-14));
  // Both walls of an axis lie the same distance off (centred), and within dx/4.
  for (int a = 0; a < 3; ++a) {
    CHECK(std::abs(f.wall_offset(a)) <= 0.25 * dx);
    CHECK(kLo[a] - f.lo[a] == Approx(hi[a] - kHi[a]).margin(1e-15));
  }
  // The cell centres the gas output and the geometry use: from the grid's corner.
  CHECK((f.cell_centre(0, 0, 0) - (f.lo + Vec3::Constant(0.5 * dx))).norm() < 1e-15);
  CHECK(f.box_lo == kLo);
  CHECK(f.box_hi == kHi);

  // The banner says where the gas walls lie, per axis that is not whole cells, with sign and
  // meaning; a whole edge adds no line.
  const std::string dir = test::tmpdir("fluid_geometry");
  std::filesystem::create_directories(dir);
  {
    Log log;
    log.set_quiet(true);
    log.open(dir + "/log.txt", false);
    fluid_banner(log, f, conform_dem_step(1e-5, f.dt));
  }
  const std::string text = test::read_text(dir + "/log.txt");
  INFO(text);
  CHECK(text.find("gas walls along x                  0.4 mm outside the particle walls (n = 22 "
                  "cells of 2 mm for a 43.2 mm edge)") != std::string::npos);
  CHECK(text.find("gas walls along z                  0.4 mm inside the particle walls (n = 62 "
                  "cells of 2 mm for a 124.8 mm edge)") != std::string::npos);
  CHECK(text.find("gas walls along y") == std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("Gas grid: a periodic edge must be whole cells and an edge under half a cell is refused",
          "[scenarios][fluid][input]") {
  // Periodic x of 43.2 mm at 2 mm: refused, naming the key, the value, why, and the fix.
  const Config c =
      Config::from_string(std::string(kGas) + "x_lo = \"periodic\"\nx_hi = \"periodic\"\n");
  try {
    read_fluid(c.section("fluid"), kLo, kHi, {true, false, false}, Vec3(0, 0, -9.81));
    FAIL("accepted");
  } catch (const InputError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("'fluid.dx' = 0.002") != std::string::npos);
    CHECK(what.find("periodic box edge along x") != std::string::npos);
    CHECK(what.find("the gas and the particles share one period") != std::string::npos);
    // 43.2 mm / 21 and / 22 cells.
    CHECK(what.find("fix: choose dx = L/n, e.g. 0.00205714285714 or 0.00196363636364 m") !=
          std::string::npos);
  }
  // A non-periodic edge under half a cell: its gas walls could not lie within dx/4.
  const Config d = Config::from_string(std::string(kGas));
  CHECK_THROWS_WITH(read_fluid(d.section("fluid"), kLo, kLo + Vec3(0.0432, 0.0009, 0.1248),
                               {false, false, false}, Vec3(0, 0, -9.81)),
                    Catch::Contains("'fluid.dx' = 0.002") && Catch::Contains("along y") &&
                        Catch::Contains("under half a cell") &&
                        Catch::Contains("fix: choose dx <= 0.0009 m"));
}

TEST_CASE("Gas output places the cells of a centred grid in SI", "[scenarios][fluid]") {
  // fluid.h5's grid gives the first cell centre at the grid's corner + dx/2, not at box.lo + dx/2,
  // and fluid.xdmf's ORIGIN_DXDYDZ the grid's corner, its nodes at the cells' corners, so that
  // ParaView lays the gas over the particles.
  const FluidConfig f = read_issue_box();
  lbm::LbmSolver gas(f.lattice());
  gas.initialize([](int, int, int, double& rho, Vec3& v) { rho = 1, v = Vec3::Zero(); });
  const std::string dir = test::tmpdir("fluid_geometry_out");
  write_fluid_snapshot(dir, gas, f, {0.0});
  const Vec3 corner = kLo + Vec3(-0.4e-3, 0, 0.4e-3);  // the design
  const Vec3 first = corner + Vec3::Constant(1e-3);
  const H5In grid(dir + "/fluid.h5");
  const auto origin = grid.doubles("/grid/origin_m"), lower = grid.doubles("/grid/lower_corner_m");
  REQUIRE(origin.size() == 3);
  REQUIRE(lower.size() == 3);
  for (int a = 0; a < 3; ++a) {
    CHECK(origin[std::size_t(a)] == Approx(first[a]).epsilon(1e-14));
    CHECK(lower[std::size_t(a)] == Approx(corner[a]).epsilon(1e-14));
  }
  const std::string xdmf = test::read_text(dir + "/fluid.xdmf");
  char want[128];  // z y x, as the writer's %.17g prints them
  std::snprintf(want, sizeof want, "%.17g %.17g %.17g</DataItem>", lower[2], lower[1], lower[0]);
  CHECK(xdmf.find(want) != std::string::npos);
  CHECK(xdmf.find("Dimensions=\"63 6 23\"") != std::string::npos);  // nodes
  CHECK(xdmf.find("Dimensions=\"62 5 22\"") != std::string::npos);  // cells
  std::filesystem::remove_all(dir);
}

// The gas config as read: an inlet ramped from a start value
// follows its closed form (ramp_from until ramp_start, linear to velocity over ramp_time), a
// start value off the inflow or a ramp that never runs is refused naming the key, and the fixes a
// stability error or a divergence message offers each pass every start-up check.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "scenarios/common/fluid_config.hpp"

#include <string>
#include <vector>

using namespace lbdem;
using namespace lbdem::scenarios;

namespace {

FluidConfig read(const std::string& z_lo) {
  const Config c = Config::from_string(
      "[fluid]\ndensity = 1.2\nviscosity = 1.8e-5\ndx = 1e-3\nmax_speed = 2.0\n"
      "[fluid.faces]\nx_lo = \"periodic\"\nx_hi = \"periodic\"\ny_lo = \"periodic\"\n"
      "y_hi = \"periodic\"\nz_lo = " +
      z_lo + "\nz_hi = { kind = \"outlet\", pressure = 0.0 }\n");
  return read_fluid(c.section("fluid"), Vec3::Zero(), Vec3(4e-3, 4e-3, 2e-2), {true, true, false},
                    Vec3(0, 0, -9.81));
}

}  // namespace

TEST_CASE("Inlet ramp from a start value: the closed form, and starts off the inflow refused",
          "[scenarios][input]") {
  const FluidConfig f = read(
      "{ kind = \"inlet\", velocity = [0.0, 0.0, 0.66], ramp_from = [0.0, 0.0, 0.0066], "
      "ramp_start = 0.1, ramp_time = 0.2 }");
  const FluidFace& in = f.faces[4];
  CHECK(in.ramped());
  // Before the ramp: the start value, also at t = 0 (what the gas starts with).
  CHECK(in.velocity_at(0).z() == 0.0066);
  CHECK(in.velocity_at(0.0999).z() == 0.0066);
  // Half-way: the mean of start and end, to round-off; after: the velocity itself.
  CHECK(in.velocity_at(0.2).z() == Approx(0.5 * (0.0066 + 0.66)).epsilon(1e-14));
  CHECK(in.velocity_at(0.31).z() == 0.66);
  CHECK(in.velocity_at(5.0).z() == 0.66);
  CHECK(in.velocity_at(0.2).head<2>().norm() == 0);
  // Without ramp_from, the ramp starts from rest as before.
  const FluidConfig g =
      read("{ kind = \"inlet\", velocity = [0.0, 0.0, 0.5], ramp_start = 0.1, ramp_time = 0.1 }");
  CHECK(g.faces[4].velocity_at(0.05).norm() == 0);
  CHECK(g.faces[4].velocity_at(0.15).z() == Approx(0.25).epsilon(1e-14));

  struct Bad {
    std::string face, why;
  } bad[] = {
      {"{ kind = \"inlet\", velocity = [0.0, 0.0, 0.5], ramp_from = [0.0, 0.0, -0.1], ramp_time = "
       "0.1 }",
       "along velocity"},
      {"{ kind = \"inlet\", velocity = [0.0, 0.0, 0.5], ramp_from = [0.1, 0.0, 0.1], ramp_time = "
       "0.1 }",
       "along velocity"},
      {"{ kind = \"inlet\", velocity = [0.0, 0.0, 0.5], ramp_from = [0.0, 0.0, 0.1] }",
       "never runs"},
  };
  for (const Bad& b : bad) {
    INFO(b.face);
    try {
      read(b.face);
      FAIL("accepted");
    } catch (const InputError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("fluid.faces.z_lo.ramp_from") != std::string::npos);
      CHECK(what.find(b.why) != std::string::npos);
      CHECK(what.find("fix:") != std::string::npos);
    }
  }
}

namespace {

// A walled pseudo-2-D bed's gas at 2 mm cells: the pressure rule (250 Pa at 1 % of rho c_s^2)
// sets dt = 8 us, which puts TRT's tau within 1e-4 of 1/2.
const char* kThinBedGas =
    "[fluid]\ndensity = 1.2\nviscosity = 1.8e-5\ndx = 0.002\nlattice_velocity = 0.1\n"
    "max_speed = 3.0\npressure_difference = 250.0\ngravity = true\n";

FluidConfig read_gas(const Config& c) {
  return read_fluid(c.section("fluid"), Vec3::Zero(), Vec3(0.044, 0.01, 0.12),
                    {false, false, false}, Vec3(0, 0, -9.81));
}

// The changes a message offers after "fix: set ", as "key = value" strings.
std::vector<std::string> offered(const std::string& message) {
  std::vector<std::string> out;
  const auto at = message.find("fix: set ");
  if (at == std::string::npos) return out;
  std::string rest = message.substr(at + 9);
  for (std::size_t cut; (cut = rest.find(", or ")) != std::string::npos; rest.erase(0, cut + 5))
    out.push_back(rest.substr(0, cut));
  out.push_back(rest);
  return out;
}

// Makes an offered change ("fluid.a = x and fluid.b = y (without fluid.c)") on the input.
void apply(Config& c, const std::string& change) {
  std::string rest = change;
  for (std::size_t at; (at = rest.find(" (without ")) != std::string::npos;) {
    const auto end = rest.find(')', at);
    c.erase(rest.substr(at + 10, end - at - 10));
    rest.erase(at, end - at + 1);
  }
  for (std::size_t cut;; rest.erase(0, cut + 5)) {
    cut = rest.find(" and ");
    const std::string one = rest.substr(0, cut);
    const auto eq = one.find(" = ");
    c.set_override(one.substr(0, eq) + "=" + one.substr(eq + 3));
    if (cut == std::string::npos) break;
  }
}

}  // namespace

TEST_CASE("Gas stability errors and divergence messages offer only changes that pass",
          "[scenarios][input]") {
  for (const char* op : {"trt", "bgk"}) {
    Config c = Config::from_string(kThinBedGas);
    c.set_override(std::string("fluid.collision=") + op);
    std::string message;
    try {
      read_gas(c);
    } catch (const InputError& e) {
      message = e.what();
    }
    INFO(message);
    REQUIRE(message.find("of 1/2") != std::string::npos);  // the tau error
    const auto fixes = offered(message);
    REQUIRE(!fixes.empty());
    // The regularized LES operator runs here (its eddy viscosity lifts the effective tau).
    CHECK(fixes.front() == std::string("fluid.collision = \"les\"") +
                               (op == std::string("trt") ? " (without fluid.magic)" : ""));
    for (const std::string& f : fixes) {
      INFO("offered: " << f);
      Config fixed = Config::from_string(kThinBedGas);
      fixed.set_override(std::string("fluid.collision=") + op);
      apply(fixed, f);
      CHECK_NOTHROW(read_gas(fixed));
      // "Raise dt" is not offered: the pressure rule already caps it.
      CHECK(f.find("fluid.dt") == std::string::npos);
    }
  }
  // A TRT input that names its magic parameter: switching to LES drops it (and says so).
  Config m = Config::from_string(kThinBedGas);
  m.set_override("fluid.magic=0.1875");
  try {
    read_gas(m);
    FAIL("accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("fluid.collision = \"les\" (without fluid.magic)") !=
          std::string::npos);
  }
  // A gas that starts: what a divergence would offer passes and changes what runs (a shorter
  // step, a finer grid or another operator: a lower lattice velocity would not change dt, which
  // the pressure rule sets here), and try_change tells a change that passes from one that does
  // not (a cell more than twice as wide as the 10 mm edge).
  Config c = Config::from_string(kThinBedGas);
  c.set_override("fluid.collision=\"les\"");
  const FluidConfig f = read_gas(c);
  REQUIRE(!f.divergence_fixes.empty());
  for (const std::string& fix : f.divergence_fixes) {
    INFO("divergence fix: " << fix);
    Config fixed = Config::from_string(kThinBedGas);
    fixed.set_override("fluid.collision=\"les\"");
    apply(fixed, fix);
    FluidConfig g;
    REQUIRE_NOTHROW(g = read_gas(fixed));
    CHECK((g.dt < f.dt || g.dx < f.dx || g.smagorinsky != f.smagorinsky));
    CHECK(g.dt <= f.dt);
  }
  REQUIRE(f.try_change);
  CHECK(f.try_change({{"dx", "0.001"}}, {}) == "");
  CHECK(f.try_change({{"dx", "0.03"}}, {}).find("under half a cell") != std::string::npos);
}

TEST_CASE("Slip walls from the config: free_slip, a slip length, and what they refuse",
          "[scenarios][input]") {
  Config c = Config::from_string(kThinBedGas);
  c.set_override("fluid.collision=\"les\"");
  c.set_override("fluid.faces.x_lo=\"free_slip\"");
  c.set_override("fluid.faces.y_lo={kind=\"wall\", slip_length=1e-4}");
  const FluidConfig f = read_gas(c);
  CHECK(f.faces[0].kind == "wall");
  CHECK(f.slip_fraction(f.faces[0]) == 1.0);
  CHECK(f.slip_fraction(f.faces[1]) == 0.0);  // x_hi: a no-slip wall by default
  // s = b / (b + 3 nu dx): the blend's slip length is 3 nu s / (1 - s) cells (slip_wall.hpp).
  const double nu = f.report.nu_lattice, b = 1e-4, s = f.slip_fraction(f.faces[2]);
  CHECK(s == Approx(b / (b + 3 * nu * f.dx)).epsilon(1e-14));
  CHECK(3 * nu * s / (1 - s) * f.dx == Approx(b).epsilon(1e-12));
  CHECK(f.lattice().faces[2].slip == s);
  // The wall function acts on every wall at rest: a slip face is refused with it.
  Config w = c.detached();
  w.set_override("fluid.wall_function=true");
  CHECK_THROWS_WITH(read_gas(w),
                    Catch::Contains("'fluid.wall_function'") && Catch::Contains("x_lo slips"));
  // A negative slip length, and an inlet ramp from faster than max_speed.
  Config n = c.detached();
  n.set_override("fluid.faces.y_hi={kind=\"wall\", slip_length=-1e-4}");
  CHECK_THROWS_WITH(read_gas(n), Catch::Contains("fluid.faces.y_hi.slip_length"));
  Config r = c.detached();
  r.set_override(
      "fluid.faces.z_lo={kind=\"inlet\", velocity=[0.0, 0.0, 0.5], ramp_from=[0.0, 0.0, 5.0], "
      "ramp_time=0.1}");
  CHECK_THROWS_WITH(read_gas(r),
                    Catch::Contains("fluid.faces.z_lo.ramp_from") && Catch::Contains("max_speed"));
}

TEST_CASE("Outlet backflow from the config: open by default, shut on request",
          "[scenarios][input]") {
  // The key reaches the lattice's face (the solver's use of it:
  // tests/lbm/test_open_boundaries.cpp).
  const FluidConfig open = read("{ kind = \"inlet\", velocity = [0.0, 0.0, 0.01] }");
  CHECK(open.faces[5].backflow);
  CHECK(open.lattice().faces[5].backflow);
  const Config c = Config::from_string(
      "[fluid]\ndensity = 1.2\nviscosity = 1.8e-5\ndx = 1e-3\nmax_speed = 2.0\n"
      "[fluid.faces]\nx_lo = \"periodic\"\nx_hi = \"periodic\"\ny_lo = \"periodic\"\n"
      "y_hi = \"periodic\"\nz_lo = { kind = \"inlet\", velocity = [0.0, 0.0, 0.01] }\n"
      "z_hi = { kind = \"outlet\", pressure = 0.0, backflow = false }\n");
  const FluidConfig shut = read_fluid(c.section("fluid"), Vec3::Zero(), Vec3(4e-3, 4e-3, 2e-2),
                                      {true, true, false}, Vec3(0, 0, -9.81));
  CHECK_FALSE(shut.faces[5].backflow);
  CHECK_FALSE(shut.lattice().faces[5].backflow);
  Config bad = c.detached();
  bad.set_override("fluid.faces.z_hi={kind=\"outlet\", pressure=0.0, backflow=0.5}");
  CHECK_THROWS_WITH(read_fluid(bad.section("fluid"), Vec3::Zero(), Vec3(4e-3, 4e-3, 2e-2),
                               {true, true, false}, Vec3(0, 0, -9.81)),
                    Catch::Contains("fluid.faces.z_hi.backflow"));
}

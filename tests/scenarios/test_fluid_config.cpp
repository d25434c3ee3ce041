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

// "fluid.dx = 0.001" -> the --set form "fluid.dx=0.001".
std::string as_set(const std::string& change) {
  const auto eq = change.find(" = ");
  return change.substr(0, eq) + "=" + change.substr(eq + 3);
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
    CHECK(fixes.front() == "fluid.collision = \"les\"");
    for (const std::string& f : fixes) {
      INFO("offered: " << f);
      Config fixed = Config::from_string(kThinBedGas);
      fixed.set_override(std::string("fluid.collision=") + op);
      fixed.set_override(as_set(f));
      CHECK_NOTHROW(read_gas(fixed));
    }
    // "Raise dt" is not offered: the pressure rule already caps it.
    for (const std::string& f : fixes) CHECK(f.find("lattice_velocity") == std::string::npos);
  }
  // A gas that starts: what a divergence would offer passes, and try_change tells a change that
  // passes from one that does not (dx no longer a divisor of the box edges).
  Config c = Config::from_string(kThinBedGas);
  c.set_override("fluid.collision=\"les\"");
  const FluidConfig f = read_gas(c);
  REQUIRE(!f.divergence_fixes.empty());
  for (const std::string& fix : f.divergence_fixes) {
    INFO("divergence fix: " << fix);
    Config fixed = Config::from_string(kThinBedGas);
    fixed.set_override("fluid.collision=\"les\"");
    fixed.set_override(as_set(fix));
    CHECK_NOTHROW(read_gas(fixed));
  }
  REQUIRE(f.try_change);
  CHECK(f.try_change("dx", "0.001") == "");
  CHECK(f.try_change("dx", "0.0007").find("whole number") != std::string::npos);
}

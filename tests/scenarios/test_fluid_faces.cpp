// The gas faces of [fluid.faces] as read from a config: an inlet ramped from a start value
// follows its closed form (ramp_from until ramp_start, linear to velocity over ramp_time), and a
// start value that is not along the inflow, or a ramp that never runs, is refused naming the key.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "scenarios/common/fluid_config.hpp"

#include <string>

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

TEST_CASE("Inlet ramp from a start value: the closed form; starts off the inflow are refused",
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

// run::CoupledGas without an exchange: the gas leads the DEM by the steps the sub-cycle gives
// (run/clock.hpp), a stop between gas steps leaves it behind and the next call completes the
// step, ramps see the time each gas step starts at, and a checkpoint whose gas step count the
// DEM's does not imply is refused. The coupled intervals are checked end to end by the box's resume
// tests (tests/scenarios).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/h5.hpp"
#include "helpers/dem_setup.hpp"
#include "lbm/lbm_solver.hpp"
#include "run/coupled_gas.hpp"

using namespace lbdem;

namespace {

std::unique_ptr<lbm::LbmSolver> small_gas() {
  lbm::LbmSettings s;
  s.nx = s.ny = s.nz = 4;
  s.collision = lbm::Bgk::from_tau(0.8);
  auto g = std::make_unique<lbm::LbmSolver>(s);
  g->initialize([](int, int, int, double& rho, Vec3& u) { rho = 1, u = Vec3::Zero(); });
  return g;
}

}  // namespace

TEST_CASE("coupled gas: three gas steps per DEM step, each ramp told its start time", "[run]") {
  const double gas_dt = 1e-5;
  const run::SubCycle sub = run::conform_dem_step(3e-5, gas_dt);
  REQUIRE(sub.gas_per_dem == 3);
  std::vector<double> ramp_times;
  run::CoupledGas gas(small_gas(), sub, gas_dt, [&](double t) { ramp_times.push_back(t); });
  dem::DemSolver dem(test::settings(sub.dem_dt), {test::glass()});
  const auto never = [] { return false; };
  for (int k = 0; k < 2; ++k) {
    gas.advance(dem, never);
    CHECK(gas.gas().steps() == 3 * (k + 1));  // the gas leads by the coming DEM step
    CHECK_FALSE(gas.behind(dem));
    dem.step();
  }
  CHECK(gas.steps_due(5) == 15);
  CHECK(gas.cycle() == 1);
  REQUIRE(ramp_times.size() == 6);
  for (std::size_t k = 0; k < ramp_times.size(); ++k)
    CHECK(ramp_times[k] == Approx(double(k) * gas_dt).margin(1e-18));
}

TEST_CASE("coupled gas: four DEM steps per gas step, and a stop leaves it behind until resumed",
          "[run]") {
  const double gas_dt = 4e-5;
  const run::SubCycle sub = run::conform_dem_step(1e-5, gas_dt);
  REQUIRE(sub.dem_per_gas == 4);
  run::CoupledGas gas(small_gas(), sub, gas_dt, nullptr);
  dem::DemSolver dem(test::settings(sub.dem_dt), {test::glass()});
  CHECK(gas.cycle() == 4);
  // A stop before the first gas step: nothing done, the gas behind the coming DEM step.
  gas.advance(dem, [] { return true; });
  CHECK(gas.gas().steps() == 0);
  CHECK(gas.behind(dem));
  // The same call again completes it; the DEM steps of the cycle then need no gas step.
  std::vector<std::int64_t> counts;
  for (int k = 0; k < 8; ++k) {
    gas.advance(dem, [] { return false; });
    counts.push_back(gas.gas().steps());
    dem.step();
  }
  CHECK(counts == std::vector<std::int64_t>{1, 1, 1, 1, 2, 2, 2, 2});

  // A checkpoint of the gas where the DEM's count puts it (2 gas steps at DEM step 8) loads; with
  // the DEM one step further (due: 3) the same gas is refused.
  namespace fs = std::filesystem;
  const std::string file =
      (fs::temp_directory_path() / ("lbdem_coupled_gas_" + std::to_string(::getpid()) + ".h5"))
          .string();
  {
    H5Out f(file);
    gas.save(f);
    f.commit();
  }
  const H5In in(file);
  CHECK_NOTHROW(gas.load(in, dem));
  CHECK(gas.gas().steps() == 2);
  dem.step();
  CHECK_THROWS_AS(gas.load(in, dem), std::runtime_error);
  fs::remove(file);
}

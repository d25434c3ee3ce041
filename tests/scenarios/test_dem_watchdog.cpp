// The DEM watchdog through the real executable: a blow-up (a forced step of 6 t_c), a non-finite
// state (a linear spring of 1e300 N/m) and an energy-balance error each stop the run with exit 3,
// one line naming the particle, the step, the quantity and the fix, status `failed`, and the
// checkpoint from before left as it was; in a coupled bed the DEM's divergence is named as the
// DEM's, not the gas's.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "core/h5.hpp"
#include "helpers/cli.hpp"

namespace fs = std::filesystem;

namespace {

using lbdem::test::cli;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

// 150 beads of the default box near its floor; dem.dt = 1e-3 s is 5.9 t_c (t_c = 1.7e-4 s at the
// preset's 2 m/s), which dem.force_dt lets pass: the first contacts throw beads out at ~200 m/s
// at step 5, against the watchdog's 22 m/s (10 x the free fall across the 0.25 m box).
const std::string kBlowUp =
    lbdem::test::beads_near_floor(150) +
    " --set run.end_time=0.06 --set output.checkpoint_interval=1.0 --set dem.force_dt=true"
    " --set dem.dt=1e-3";

// stderr also carries the progress line; the error is the line that starts with "lbdem:".
std::string error_line(const std::string& err) {
  const auto at = err.find("lbdem:");
  return at == std::string::npos ? std::string() : err.substr(at);
}

bool finite_checkpoint(const std::string& file) {
  const lbdem::H5In ck(file);
  const auto x = ck.doubles("/dem/x");
  return !x.empty() && std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

TEST_CASE("the DEM watchdog stops a blow-up at its step and keeps the checkpoint before it",
          "[scenarios][watchdog]") {
  const std::string out = tmpdir("dem_blowup");
  // Three sound steps first, ending with a checkpoint at t = 3 ms; then the same run resumed to
  // its end diverges at step 5, before any output: the checkpoint must stay byte for byte.
  const auto first = cli("run box --out " + out + kBlowUp + " --set run.end_time=0.003");
  INFO(first.err);
  REQUIRE(first.code == 0);
  const std::string before = read_text(out + "/checkpoint.h5");
  REQUIRE(finite_checkpoint(out + "/checkpoint.h5"));
  const auto r = cli("run --resume " + out + " --set run.end_time=0.06");
  const std::string line = error_line(r.err);
  INFO(r.err);
  CHECK(r.code == 3);
  CHECK(line.rfind("lbdem: error: DEM diverged at t = 0.005 s (DEM step 5", 0) == 0);
  CHECK(std::count(line.begin(), line.end(), '\n') == 1);
  for (const char* s :
       {"particle id ", "above the watchdog's limit of 22.1472 m/s (10 x", "5.95 t_c",
        "lower dem.dt to at most t_c/20", "dem.force_dt", "youngs_modulus"})
    CHECK(line.find(s) != std::string::npos);
  CHECK(read_text(out + "/status").rfind("failed (diverged", 0) == 0);
  CHECK(read_text(out + "/log.txt").find("error: DEM diverged") != std::string::npos);
  CHECK(read_text(out + "/checkpoint.h5") == before);
  for (const auto& e : fs::recursive_directory_iterator(out)) CHECK(e.path().extension() != ".tmp");
  fs::remove_all(out);
}

TEST_CASE("the DEM watchdog names a non-finite particle state", "[scenarios][watchdog]") {
  // A linear spring of 1e300 N/m (t_c rounds to 0): the first contact force overflows and the
  // state turns NaN; without the watchdog the run writes NaN rows and an end checkpoint of NaN.
  const std::string out = tmpdir("dem_nan");
  const auto r = cli("run box --out " + out + kBlowUp +
                     " --set contact.normal=\"linear\" --set materials[0].stiffness=1e300"
                     " --set dem.dt=1e-5 --set dem.max_speed_factor=1e9");
  const std::string line = error_line(r.err);
  INFO(r.err);
  CHECK(r.code == 3);
  CHECK(line.rfind("lbdem: error: DEM diverged at t = ", 0) == 0);
  CHECK(line.find("has a non-finite position") != std::string::npos);
  CHECK(line.find("check materials.stiffness") != std::string::npos);
  CHECK(read_text(out + "/status").rfind("failed", 0) == 0);
  CHECK(finite_checkpoint(out + "/checkpoint.h5"));
  // Every row written is finite.
  const std::string ts = read_text(out + "/timeseries.csv");
  CHECK(ts.find("nan") == std::string::npos);
  CHECK(ts.find("inf") == std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("the DEM watchdog stops an energy-balance error beyond its fraction",
          "[scenarios][watchdog]") {
  // The blow-up with no speed bound: the row at step 5 finds the energy balance off by all the
  // energy moved (a step of 6 t_c makes energy from nothing).
  const std::string out = tmpdir("dem_energy");
  const auto r = cli("run box --out " + out + kBlowUp + " --set dem.max_speed_factor=1e9");
  const std::string line = error_line(r.err);
  INFO(r.err);
  CHECK(r.code == 3);
  CHECK(line.find("the energy balance error") != std::string::npos);
  CHECK(line.find("above dem.max_energy_error = 0.1") != std::string::npos);
  CHECK(line.find("the fastest particle, id ") != std::string::npos);
  CHECK(line.find("lower dem.dt to at most t_c/20") != std::string::npos);
  // The same run with the fraction raised past the error goes on to the next check.
  const std::string out2 = tmpdir("dem_energy_loose");
  const auto loose = cli("run box --out " + out2 + kBlowUp +
                         " --set dem.max_speed_factor=1e9 --set dem.max_energy_error=1e6");
  CHECK(error_line(loose.err).find("the energy balance error") == std::string::npos);
  fs::remove_all(out);
  fs::remove_all(out2);
}

TEST_CASE("a coupled bed whose DEM step is 40 t_c is stopped by the DEM watchdog, not the gas's",
          "[scenarios][watchdog]") {
  // The default fluidized bed with dem.dt = 8e-4 s: the parcels step 3.2 ms, 40.6 t_c. The second
  // DEM step throws a parcel out at 78 m/s, above the gas watchdog's 55.9 m/s that bounds what the
  // gas can carry; the gas is still sound then, and the message says so.
  const std::string out = tmpdir("dem_bed");
  const auto r = cli("run fluidized_bed --out " + out +
                     " --set run.end_time=0.02 --set dem.force_dt=true --set dem.dt=8e-4");
  const std::string line = error_line(r.err);
  INFO(r.err);
  CHECK(r.code == 3);
  CHECK(line.rfind("lbdem: error: DEM diverged at t = ", 0) == 0);
  CHECK(line.find("40.6 t_c") != std::string::npos);
  CHECK(line.find("the gas watchdog's speed limit") != std::string::npos);
  CHECK(line.find("The gas is within its limits") != std::string::npos);
  CHECK(line.find("gas diverged") == std::string::npos);
  CHECK(read_text(out + "/status").rfind("failed (diverged", 0) == 0);
  fs::remove_all(out);
}

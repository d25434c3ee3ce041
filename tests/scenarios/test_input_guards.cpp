// Inputs that would switch a run's protection off or make it do nothing are refused before
// anything is written (exit 2, one line naming the key the user wrote, no run folder): a checkpoint
// interval of 0 or below, two [[materials]] of one name, a step that makes no step to
// run.end_time or is not a finite time. Implausible material values only warn, one line each.
#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/h5.hpp"
#include "helpers/cli.hpp"

namespace fs = std::filesystem;

namespace {

using lbdem::test::cli;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

// 150 beads of the default box near its floor, for 2 ms.
const std::string kSmall = lbdem::test::beads_near_floor(150) + " --set run.end_time=0.002";

// Runs the box with `args`; checks exit 2, one line naming `key` with a fix, and no run folder.
void refused(const std::string& args, const std::string& key) {
  const std::string out = tmpdir("guard");
  const auto r = cli("run box --out " + out + kSmall + " " + args);
  INFO(args << " -> " << r.err);
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: '" + key + "'", 0) == 0);
  CHECK(r.err.find("fix:") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(out));
}

}  // namespace

TEST_CASE("a checkpoint interval of 0 or below is refused", "[scenarios][input]") {
  refused("--set output.checkpoint_interval=0", "output.checkpoint_interval");
  refused("--set output.checkpoint_interval=-1", "output.checkpoint_interval");
}

TEST_CASE("two [[materials]] of one name are refused", "[scenarios][input]") {
  const std::string file = tmpdir("two_glasses") + ".toml";
  std::ofstream(file) << read_text(std::string(LBDEM_SOURCE_DIR) +
                                   "/scenarios/box/presets/default.toml")
                      << "\n[[materials]]\nname = \"glass\"\ndensity = 1000\n";
  refused("--config " + file, "materials[1].name");
  CHECK(cli("run box --config " + file).err.find("materials[0] has this name too") !=
        std::string::npos);
  fs::remove(file);
}

TEST_CASE("a step that makes no step, or too many, is refused naming the key written",
          "[scenarios][input]") {
  // dem.dt longer than the run, and one that would take 2e27 steps.
  refused("--set dem.force_dt=true --set dem.dt=1e300", "dem.dt");
  refused("--set dem.dt=1e-30", "dem.dt");
  // A density that makes t_c, and so the default step, infinite: the density is named, not
  // dem.dt = inf.
  refused("--set materials[0].density=1e300", "materials[0].density");
  refused("--set materials[0].youngs_modulus=1e300", "materials[0].youngs_modulus");
  // An end before the first step.
  refused("--set run.end_time=1e-12", "run.end_time");
}

TEST_CASE("an implausible material value warns in one line and the run goes on",
          "[scenarios][input]") {
  // 2.5 kg/m^3: a density in g/cm^3. The run is valid and finishes.
  const std::string out = tmpdir("plausible");
  const auto r = cli("run box --out " + out + kSmall + " --set materials[0].density=2.5");
  INFO(r.err);
  CHECK(r.code == 0);
  const std::string log = read_text(out + "/log.txt");
  const std::string w = "warning: 'materials[0].density' = 2.5: outside 100 - 25000 kg/m^3";
  CHECK(log.find(w) != std::string::npos);
  CHECK(log.find(w, log.find(w) + 1) == std::string::npos);  // once
  CHECK(log.find("warning: 'materials[0].youngs_modulus'") == std::string::npos);
  CHECK(read_text(out + "/status") == "finished\n");
  fs::remove_all(out);
}

TEST_CASE("checkpoints are switched off only by name, with a warning", "[scenarios][input]") {
  refused("--set output.checkpoint_interval=sometimes", "output.checkpoint_interval");
  const std::string out = tmpdir("never");
  const auto r = cli("run box --out " + out + kSmall +
                     " --set run.end_time=0.02 --set output.checkpoint_interval=never");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(read_text(out + "/log.txt")
            .find("warning: output.checkpoint_interval = \"never\": checkpoints are written only "
                  "at the start, at the end") != std::string::npos);
  // The generation before the end's is the start's: none between.
  CHECK(lbdem::H5In(out + "/checkpoint.prev.h5").attr_double("time_s", "/dem") == 0);
  CHECK(lbdem::H5In(out + "/checkpoint.h5").attr_double("time_s", "/dem") ==
        Approx(0.02).margin(1e-5));
  fs::remove_all(out);
}

TEST_CASE("an error's echo of a huge value is cut to one short line", "[scenarios][input]") {
  std::string big = "[0.0";
  for (int k = 0; k < 10000; ++k) big += ", 0.0";
  big += "]";
  const std::string out = tmpdir("huge_echo");
  const auto r = cli("run box --out " + out + kSmall + " --set 'physics.gravity=" + big + "'");
  INFO(r.err.substr(0, 400));
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: 'physics.gravity' = [0, 0", 0) == 0);
  CHECK(r.err.find("characters)") != std::string::npos);
  CHECK(r.err.size() < 400);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("an input error found once the run goes leaves no run folder", "[scenarios][input]") {
  // A box whose periodic y (6 mm) is shorter than two neighbour cells of its 2.2 mm beads: the
  // first neighbour search, in the first step, finds it.
  const std::string thin =
      " --set box.y_lo=periodic --set box.y_hi=periodic --set 'box.hi=[0.06,0.006,0.25]' --set "
      "'fill=[{count = 50, lo = [0, 0, 0.03], hi = [0.06, 0.006, 0.25], material = \"glass\", "
      "radius = {kind = \"uniform\", min = 1.8e-3, max = 2.2e-3}}]' --set run.end_time=0.01";
  const std::string out = tmpdir("thin_box");
  const auto r = cli("run box" + thin + " --out " + out);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: 'domain' = periodic length 0.006 m", 0) == 0);
  CHECK_FALSE(fs::exists(out));
  // An empty folder given as --out stays, empty.
  fs::create_directories(out);
  CHECK(cli("run box" + thin + " --out " + out).code == 2);
  CHECK(fs::is_directory(out));
  CHECK(fs::is_empty(out));
  fs::remove_all(out);
}

TEST_CASE("a run that cannot fit is refused before it allocates or places anything",
          "[scenarios][input]") {
  // Sizes beyond any machine's memory, so that the outcome does not depend on this one's: 10^12
  // gas cells at 222 B (222 TB) and 10^11 particles at 1 kB (100 TB).
  const std::string channel =
      "--config " + std::string(LBDEM_SOURCE_DIR) + "/scenarios/box/presets/gas_channel.toml";
  const std::string out = tmpdir("too_big");
  auto r = cli("run box " + channel + " --set 'box.hi=[1,1,1]' --set fluid.dx=1e-4 --out " + out);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: 'fluid.dx' = 0.0001: the gas's 1.0006e+12 cells", 0) == 0);
  CHECK(r.err.find("222 TB (2.22e+14 B)") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  const std::string huge_box =
      " --set 'box.hi=[1000,1000,1000]' --set 'fill[0].lo=[0,0,0]' --set "
      "'fill[0].hi=[1000,1000,1000]'";
  r = cli("run box --out " + out + " --set fill[0].count=100000000000" + huge_box);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: 'fill[0].count' = 100000000000: at least 1e+11 particles", 0) ==
        0);
  CHECK(r.err.find("100 TB (1e+14 B)") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // A mass is counted in the largest radius: the fewest particles it can mean.
  r = cli("run box --out " + out + " --set fill[0].count=0 --set fill[0].mass=1e9" + huge_box);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: 'fill[0].mass' = 1e+09: at least", 0) == 0);
  CHECK_FALSE(fs::exists(out));
  // More particle volume than the region holds: refused at once, not after minutes of tries.
  refused("--set fill[0].count=100000000", "fill[0].count");
}

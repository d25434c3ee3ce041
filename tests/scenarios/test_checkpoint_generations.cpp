// Two checkpoint generations (RunLoop): checkpoint.h5 and checkpoint.prev.h5, each verified by
// the checksums of its datasets (checkpoint_check.hpp); a resume takes the newest that verifies and
// says which, and refuses with one line when none does.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "core/h5.hpp"
#include "helpers/checkpoint_edit.hpp"
#include "helpers/cli.hpp"

namespace fs = std::filesystem;

namespace {

using lbdem::test::cli;
using lbdem::test::flip_bit;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

// 150 beads of the default box near its floor; checkpoints at 0, 20 and 30 ms (instants are whole
// steps of 6.7 us, so within a step of those).
const std::string kSmall = lbdem::test::beads_near_floor(150) +
                           " --set run.end_time=0.03 --set output.checkpoint_interval=0.02";

double checkpoint_time(const std::string& file) {
  return lbdem::H5In(file).attr_double("time_s", "/dem");
}

}  // namespace

TEST_CASE("a run keeps two checkpoint generations, the newest in checkpoint.h5",
          "[scenarios][checkpoint]") {
  const std::string out = tmpdir("generations");
  REQUIRE(cli("run box --out " + out + kSmall).code == 0);
  CHECK(checkpoint_time(out + "/checkpoint.h5") == Approx(0.03).margin(1e-5));
  CHECK(checkpoint_time(out + "/checkpoint.prev.h5") == Approx(0.02).margin(1e-5));
  CHECK(lbdem::H5In(out + "/checkpoint.prev.h5").has_checksums());
  for (const auto& e : fs::recursive_directory_iterator(out)) CHECK(e.path().extension() != ".tmp");
  fs::remove_all(out);
}

TEST_CASE("a resume takes the newest checkpoint that verifies, says which, or refuses",
          "[scenarios][checkpoint]") {
  const std::string out = tmpdir("generation_resume");
  REQUIRE(cli("run box --out " + out + kSmall).code == 0);
  // A flipped bit in checkpoint.h5: the resume goes back to 20 ms, and says so.
  flip_bit(out + "/checkpoint.h5", "/dem/x");
  const auto r = cli("run --resume " + out + " --set run.end_time=0.045");
  INFO(r.err);
  CHECK(r.code == 0);
  const std::string log = read_text(out + "/log.txt");
  CHECK(log.find("warning: checkpoint.h5 does not verify (dataset /dem/x fails its checksum); "
                 "resuming from checkpoint.prev.h5") != std::string::npos);
  CHECK(log.find("resumed from " + out + "/checkpoint.prev.h5 at t = 0.02") != std::string::npos);
  CHECK(checkpoint_time(out + "/checkpoint.h5") == Approx(0.045).margin(1e-5));
  // Both generations damaged: refused in one line, exit 2.
  flip_bit(out + "/checkpoint.h5", "/dem/x");
  flip_bit(out + "/checkpoint.prev.h5", "/dem/x");
  const auto none = cli("run --resume " + out + " --set run.end_time=0.06");
  CHECK(none.code == 2);
  CHECK(none.err.rfind("lbdem: error: '--resume'", 0) == 0);
  CHECK(none.err.find("no checkpoint verifies") != std::string::npos);
  fs::remove_all(out);
}

// output.checkpoint_wall_interval: a checkpoint after that much wall time at whatever step the run
// has reached. At 1 ns one is written every step, so the generation before the last is one step
// (6.7 us) before the end instead of the start; the results are those of the run without.
TEST_CASE("a checkpoint is written after checkpoint_wall_interval of wall time, results unchanged",
          "[scenarios][checkpoint]") {
  const std::string a = tmpdir("wall_checkpoint_off"), b = tmpdir("wall_checkpoint_on");
  const std::string run = lbdem::test::beads_near_floor(150) +
                          " --set run.end_time=0.002 --set output.checkpoint_interval=0.002";
  REQUIRE(cli("run box --out " + a + run).code == 0);
  REQUIRE(cli("run box --out " + b + run + " --set output.checkpoint_wall_interval=1e-9").code ==
          0);
  CHECK(checkpoint_time(a + "/checkpoint.prev.h5") == 0.0);
  const double end = checkpoint_time(b + "/checkpoint.h5");
  CHECK(end == Approx(0.002).margin(1e-5));
  CHECK(checkpoint_time(b + "/checkpoint.prev.h5") == Approx(end - 6.7e-6).margin(1e-6));
  CHECK(read_text(a + "/timeseries.csv") == read_text(b + "/timeseries.csv"));
  // Bad values: one line naming the key, exit 2, nothing written.
  for (const std::string v : {"0", "'\"often\"'"}) {
    const std::string c = tmpdir("wall_checkpoint_bad");
    const auto r = cli("run box --out " + c + run + " --set output.checkpoint_wall_interval=" + v);
    CHECK(r.code == 2);
    CHECK(r.err.find("'output.checkpoint_wall_interval'") != std::string::npos);
    CHECK(!fs::exists(c));
  }
  fs::remove_all(a);
  fs::remove_all(b);
}

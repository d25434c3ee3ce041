// Two checkpoint generations (DemDriver): checkpoint.h5 and checkpoint.prev.h5, each verified by
// the checksums of its datasets (checkpoint_check.hpp); a resume takes the newest that verifies and
// says which, and refuses with one line when none does.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <hdf5.h>

#include "core/h5.hpp"
#include "helpers/cli.hpp"

namespace fs = std::filesystem;

namespace {

using lbdem::test::cli;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

// 150 beads of the default box near its floor; checkpoints at 0, 20 and 30 ms (instants are whole
// steps of 6.7 us, so within a step of those).
const std::string kSmall =
    " --set fill[0].count=150 --set 'fill[0].lo=[0.0,0.0,0.0]' --set 'fill[0].hi=[0.06,0.06,0.03]'"
    " --set run.end_time=0.03 --set output.checkpoint_interval=0.02";

double checkpoint_time(const std::string& file) {
  return lbdem::H5In(file).attr_double("time_s", "/dem");
}

// Moves the first particle's x by one ulp in place, as a bit flipped on disk would.
void flip_one_position(const std::string& file) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t d = H5Dopen2(f, "/dem/x", H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  std::vector<double> x(std::size_t(H5Sget_simple_extent_npoints(space)));
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data());
  x[0] = std::nextafter(x[0], 1.0);
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
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
  flip_one_position(out + "/checkpoint.h5");
  const auto r = cli("run --resume " + out + " --set run.end_time=0.045");
  INFO(r.err);
  CHECK(r.code == 0);
  const std::string log = read_text(out + "/log.txt");
  CHECK(log.find("warning: checkpoint.h5 does not verify (dataset /dem/x fails its checksum); "
                 "resuming from checkpoint.prev.h5") != std::string::npos);
  CHECK(log.find("resumed from " + out + "/checkpoint.prev.h5 at t = 0.02") != std::string::npos);
  CHECK(checkpoint_time(out + "/checkpoint.h5") == Approx(0.045).margin(1e-5));
  // Both generations damaged: refused in one line, exit 2.
  flip_one_position(out + "/checkpoint.h5");
  flip_one_position(out + "/checkpoint.prev.h5");
  const auto none = cli("run --resume " + out + " --set run.end_time=0.06");
  CHECK(none.code == 2);
  CHECK(none.err.rfind("lbdem: error: '--resume'", 0) == 0);
  CHECK(none.err.find("no checkpoint verifies") != std::string::npos);
  fs::remove_all(out);
}

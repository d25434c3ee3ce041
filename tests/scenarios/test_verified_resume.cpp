// Verified resume (checkpoint_check.hpp): a checkpoint whose data fails its checksums, that is
// from another scenario or other physics, or whose folder lost the outputs it appends to, is
// refused with one line and exit 2 and the folder left byte for byte as it was; a finished run is
// left as it is; run.end_time and output.* may change; a checkpoint that records no config
// resumes with a warning.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <hdf5.h>

#include "dem/dem_solver.hpp"
#include "helpers/checkpoint_edit.hpp"
#include "helpers/cli.hpp"

namespace fs = std::filesystem;

namespace {

using lbdem::test::cli;
using lbdem::test::flip_bit;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

// 40 beads of the default box near its floor, to 4 ms: checkpoints at 0, 2 and 4 ms (well under a
// second).
const std::string kTiny = lbdem::test::beads_near_floor(40) +
                          " --set run.end_time=0.004 --set output.checkpoint_interval=0.002";

// Every file below `dir` with its bytes.
std::map<std::string, std::string> tree(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      std::ifstream f(e.path(), std::ios::binary);
      out[fs::relative(e.path(), dir).string()] =
          std::string(std::istreambuf_iterator<char>(f), {});
    }
  return out;
}

std::string finished_run(const std::string& name, const std::string& args = kTiny) {
  const std::string out = tmpdir(name);
  REQUIRE(cli("run box --out " + out + args).code == 0);
  REQUIRE(read_text(out + "/status") == "finished\n");
  return out;
}

// Flips one bit of the first value of a double dataset in place, as a disk might.
// The checkpoint as an lbdem from before verified resumes wrote it: no identity (/run), no count
// of checksummed datasets.
void strip_identity(const std::string& file) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  CHECK(H5Ldelete(f, "/run", H5P_DEFAULT) >= 0);
  CHECK(H5Adelete(f, "checksummed_datasets") >= 0);
  H5Fclose(f);
}

void replace_in(const std::string& file, const std::string& from, const std::string& to) {
  std::string text = read_text(file);
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  std::ofstream(file, std::ios::trunc) << text;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A refused resume: exit 2, one line naming `what`, and the folder as it was.
void check_refused(const std::string& dir, const std::string& what) {
  const auto before = tree(dir);
  const auto r = cli("run --resume " + dir + " --set run.end_time=0.006");
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.err.rfind("lbdem: error: '--resume' = " + dir + ": ", 0) == 0);
  CHECK(count(r.err, "\n") == 1);
  CHECK(r.err.find(what) != std::string::npos);
  CHECK(tree(dir) == before);
}

}  // namespace

TEST_CASE("a bit flipped in any checkpoint dataset is caught", "[scenarios][checkpoint]") {
  const std::string out = finished_run("flip_any");
  // The angular velocities: a dataset the positions-and-velocities checksum did not cover.
  flip_bit(out + "/checkpoint.h5", "/dem/omega");
  const auto one = cli("run --resume " + out + " --set run.end_time=0.006");
  INFO(one.err);
  CHECK(one.code == 0);
  CHECK(read_text(out + "/log.txt")
            .find("warning: checkpoint.h5 does not verify (dataset /dem/omega fails its "
                  "checksum); resuming from checkpoint.prev.h5") != std::string::npos);
  // Both generations bad: refused, and nothing touched (status included).
  flip_bit(out + "/checkpoint.h5", "/dem/radius");
  flip_bit(out + "/checkpoint.prev.h5", "/dem/inertia");
  check_refused(out,
                "no checkpoint verifies: checkpoint.h5 (dataset /dem/radius fails its "
                "checksum), checkpoint.prev.h5 (dataset /dem/inertia fails its checksum)");
  fs::remove_all(out);
}

TEST_CASE("a checkpoint copied in from another run is refused without a crash",
          "[scenarios][checkpoint]") {
  const std::string box = finished_run("foreign_box");
  // A fluidized bed's (gas and all) in a box folder.
  const std::string bed = tmpdir("foreign_bed");
  REQUIRE(cli("run fluidized_bed --threads 1 --set run.end_time=0.0005 --out " + bed).code == 0);
  fs::copy_file(bed + "/checkpoint.h5", box + "/checkpoint.h5",
                fs::copy_options::overwrite_existing);
  check_refused(box,
                "checkpoint.h5 is from a fluidized_bed run and this folder's config.toml is "
                "for box");
  // Another box run's, of other particles: the keys that differ are named (the step and skin
  // follow the radii drawn).
  const std::string other = finished_run("foreign_other", kTiny + " --set fill[0].count=50");
  fs::copy_file(other + "/checkpoint.h5", box + "/checkpoint.h5",
                fs::copy_options::overwrite_existing);
  check_refused(box, "fill[0].count = 50 there, 40 in config.toml");
  for (const auto& d : {box, bed, other}) fs::remove_all(d);
}

TEST_CASE("a config edited to other physics is refused naming the key", "[scenarios][checkpoint]") {
  const std::string out = finished_run("edited_physics");
  replace_in(out + "/config.toml", "restitution = 0.5", "restitution = 0.7");
  check_refused(out,
                "checkpoint.h5 was written under other physics: materials[0].restitution = "
                "0.5 there, 0.7 in config.toml; fix: put the values back");
  fs::remove_all(out);
}

TEST_CASE("a checkpoint of another DEM layout is refused naming both layouts",
          "[scenarios][checkpoint]") {
  // As an lbdem whose contact records had another shape wrote it: only the recorded layout
  // differs here, so the refusal comes from the check, before any dataset is read.
  const std::string out = finished_run("other_layout");
  const hid_t f = H5Fopen((out + "/checkpoint.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  CHECK(H5Adelete_by_name(f, "/dem", "layout_version", H5P_DEFAULT) >= 0);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate_by_name(f, "/dem", "layout_version", H5T_STD_I64LE, space, H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(a >= 0);
  const std::int64_t old_layout = lbdem::dem::DemSolver::kCheckpointLayout - 1;
  CHECK(H5Awrite(a, H5T_NATIVE_INT64, &old_layout) >= 0);
  H5Aclose(a);
  H5Sclose(space);
  H5Fclose(f);
  check_refused(out, "checkpoint.h5 holds the DEM state in layout " + std::to_string(old_layout) +
                         ", this lbdem reads layout " +
                         std::to_string(lbdem::dem::DemSolver::kCheckpointLayout));
  fs::remove_all(out);
}

TEST_CASE("run.end_time and output.* edited in config.toml are accepted",
          "[scenarios][checkpoint]") {
  const std::string out = finished_run("edited_output");
  replace_in(out + "/config.toml", "end_time = 0.0040000000000000001", "end_time = 0.006");
  replace_in(out + "/config.toml", "\ninterval = 0.0050000000000000001", "\ninterval = 0.001");
  const auto r = cli("run --resume " + out);
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(read_text(out + "/status") == "finished\n");
  CHECK(read_text(out + "/log.txt").find("warning") == std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("resuming a finished run changes nothing", "[scenarios][checkpoint]") {
  const std::string out = finished_run("finished_again");
  const auto before = tree(out);
  const auto r = cli("run --resume " + out);
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(tree(out) == before);  // timeseries.csv keeps its last row, log.txt has no new line
  // Raised, it goes on.
  REQUIRE(cli("run --resume " + out + " --set run.end_time=0.006").code == 0);
  CHECK(tree(out).at("timeseries.csv").size() > before.at("timeseries.csv").size());
  fs::remove_all(out);
}

TEST_CASE("a resume whose snapshots are gone is refused before anything is written",
          "[scenarios][checkpoint]") {
  const std::string out = finished_run("no_snapshots");
  fs::remove_all(out + "/snapshots");
  check_refused(out, "snapshots/particles_000000.h5 is missing");
  fs::remove_all(out);
}

TEST_CASE("a checkpoint that records no config resumes with a warning", "[scenarios][checkpoint]") {
  const std::string out = finished_run("old_format");
  strip_identity(out + "/checkpoint.h5");
  strip_identity(out + "/checkpoint.prev.h5");
  const auto r = cli("run --resume " + out + " --set run.end_time=0.006");
  INFO(r.err);
  CHECK(r.code == 0);
  const std::string log = read_text(out + "/log.txt");
  CHECK(count(log, "warning") == 1);
  CHECK(log.find("warning: checkpoint.h5 records no config (written before lbdem verified "
                 "resumes): the config could not be verified against it") != std::string::npos);
  // The checkpoints it writes record it again.
  CHECK(cli("run --resume " + out + " --set run.end_time=0.008").code == 0);
  CHECK(count(read_text(out + "/log.txt"), "warning") == 1);
  fs::remove_all(out);
}

// The XDMF files of a run folder as text (run/xdmf.hpp), where no ParaView is
// needed: particle and gas grids carry the same time values, every particle grid has its vertex
// cells and arrays, the gas grid's nodes are the cells' corners, and a snapshot from an older
// build is described by what it holds. tests/tools/test_paraview_outputs.py opens the same files
// with ParaView where it is installed.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/h5.hpp"
#include "helpers/cli.hpp"
#include "helpers/csv_table.hpp"
#include "run/xdmf.hpp"

namespace {

using lbdem::test::cli;
using lbdem::test::read_text;
using lbdem::test::tmpdir;

/// Every value of attribute `attr` in `xml`, in order.
std::vector<std::string> values_of(const std::string& xml, const std::string& attr) {
  std::vector<std::string> out;
  const std::string key = attr + "=\"";
  for (std::size_t at = xml.find(key); at != std::string::npos; at = xml.find(key, at + 1)) {
    const std::size_t from = at + key.size();
    out.push_back(xml.substr(from, xml.find('"', from) - from));
  }
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("particle and gas XDMF share time values and describe every snapshot",
          "[scenarios][output]") {
  // The fluidized bed's preset for 2 ms, a snapshot every 1 ms.
  const std::string one = tmpdir("xdmf_bed");
  REQUIRE(cli("run fluidized_bed --threads 1 --out " + one +
              " --set run.end_time=0.002 --set output.snapshot_interval=0.001")
              .code == 0);
  const auto times = lbdem::H5In(one + "/particles.h5").doubles("/time_s");
  REQUIRE(times.size() == 3);
  const std::string px = read_text(one + "/particles.xdmf"), gx = read_text(one + "/fluid.xdmf");
  std::vector<std::string> want;
  for (double t : times) want.push_back(lbdem::run::xdmf_time(t));
  CHECK(values_of(px, "Value") == want);  // one text per instant: one time step in ParaView
  CHECK(values_of(gx, "Value") == want);
  CHECK(std::stod(want[1]) == times[1]);  // the text reads back to the same double

  // Particles: one vertex cell per particle, with the snapshot's connectivity and every array.
  const std::string last = "snapshots/particles_000002.h5";
  const lbdem::H5In snap(one + "/" + last);
  const auto vertex = snap.int32s("/vertex_index");
  const std::size_t n = vertex.size();
  REQUIRE(n == snap.doubles("/radius_m").size());
  for (std::size_t k = 0; k < n; ++k) CHECK(vertex[k] == std::int32_t(k));
  CHECK(px.find("NumberOfElements=\"" + std::to_string(n) + "\" NodesPerElement=\"1\"><DataItem") !=
        std::string::npos);
  CHECK(count(px, ":/vertex_index</DataItem>") == 3);
  for (const char* a : {"radius_m", "velocity_m_per_s", "angular_velocity_rad_per_s", "force_N",
                        "id", "material", "coordination_number"})
    CHECK(count(px, std::string("Attribute Name=\"") + a + "\"") == 3);
  // Gas: nodes at the cells' corners (one more per axis than the cells), cell data, solid mask.
  const lbdem::H5In grid(one + "/fluid.h5");
  const auto cells = grid.int32s("/grid/cells");
  const std::string nodes = std::to_string(cells[2] + 1) + " " + std::to_string(cells[1] + 1) +
                            " " + std::to_string(cells[0] + 1);
  CHECK(count(gx, "3DCoRectMesh\" Dimensions=\"" + nodes + "\"") == 3);
  CHECK(count(gx, "Center=\"Node\"") == 0);
  CHECK(count(gx, "Attribute Name=\"solid\"") == 3);
  const auto solid = lbdem::H5In(one + "/snapshots/fluid_000002.h5").uint8s("/solid");
  CHECK(solid.size() == std::size_t(cells[0]) * std::size_t(cells[1]) * std::size_t(cells[2]));
  std::filesystem::remove_all(one);
}

TEST_CASE("snapshot coordination numbers count the contacts and match on 2 threads",
          "[scenarios][output]") {
  // 150 beads dropped onto the box floor for 0.06 s (a few touch by then), on 1 and on 2 threads.
  const std::string one = tmpdir("xdmf_box_1"), two = tmpdir("xdmf_box_2");
  const std::string args = lbdem::test::beads_near_floor(150) + " --set run.end_time=0.06";
  REQUIRE(cli("run box --threads 1 --out " + one + args).code == 0);
  REQUIRE(cli("run box --threads 2 --out " + two + args).code == 0);
  const auto times = lbdem::H5In(one + "/particles.h5").doubles("/time_s");
  REQUIRE(times.size() >= 2);
  char last[64];
  std::snprintf(last, sizeof last, "/snapshots/particles_%06zu.h5", times.size() - 1);
  const lbdem::H5In a(one + last), b(two + last);
  // Each touching pair is one of contacts_pp in the last row (the run's end, as the snapshot; the
  // csv's 9 digits hold the time to 5e-9) and adds one to the coordination number of each of its
  // two particles.
  const auto c = a.int32s("/coordination_number");
  std::int64_t sum = 0;
  for (auto v : c) sum += v;
  const auto table = lbdem::test::read_csv(one + "/timeseries.csv");
  CHECK(table.rows.back()[std::size_t(table.col("time_s"))] == Approx(times.back()).epsilon(1e-8));
  CHECK(sum == 2 * std::int64_t(table.rows.back()[std::size_t(table.col("contacts_pp"))]));
  CHECK(sum > 0);
  const auto force = a.doubles("/force_N");
  REQUIRE(force.size() == 3 * c.size());
  CHECK(force == b.doubles("/force_N"));  // the same bits
  CHECK(c == b.int32s("/coordination_number"));
  std::filesystem::remove_all(one);
  std::filesystem::remove_all(two);
}

TEST_CASE("particle XDMF names only what an older snapshot holds", "[scenarios][output]") {
  // A snapshot as builds before the vertex cells wrote it: no connectivity, force or coordination
  // number. Its grid keeps the topology without connectivity and the arrays it has.
  const std::string dir = tmpdir("xdmf_old");
  std::filesystem::create_directories(dir + "/snapshots");
  {
    lbdem::H5Out f(dir + "/snapshots/particles_000000.h5");
    f.write("/position_m", std::vector<lbdem::Vec3>(2, lbdem::Vec3::Zero()));
    f.write("/radius_m", std::vector<double>{1e-3, 1e-3});
    f.write("/velocity_m_per_s", std::vector<lbdem::Vec3>(2, lbdem::Vec3::Zero()));
    f.write("/id", std::vector<std::int64_t>{0, 1});
    f.commit();
  }
  lbdem::run::write_particles_xdmf(dir, {0.25});
  const std::string x = read_text(dir + "/particles.xdmf");
  CHECK(x.find("<Time Value=\"0.25\"/>") != std::string::npos);
  CHECK(x.find("NumberOfElements=\"2\" NodesPerElement=\"1\"></Topology>") != std::string::npos);
  CHECK(x.find("radius_m") != std::string::npos);
  CHECK(x.find("Attribute Name=\"id\"") != std::string::npos);
  for (const char* absent : {"vertex_index", "force_N", "coordination_number", "material"})
    CHECK(x.find(absent) == std::string::npos);
  std::filesystem::remove_all(dir);
}

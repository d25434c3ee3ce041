// docs/config.md against the code: it must be what `lbdem-cli config` prints, and every key the
// scenarios read from their presets must have a unit and meaning (scenarios/config_reference.cpp).
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "core/config.hpp"
#include "scenarios/config_reference.hpp"

using namespace lbdem;
using namespace lbdem::scenarios;

TEST_CASE("docs/config.md is the generated reference and documents every key read", "[scenarios]") {
  // Builds each scenario from one preset of every kind (presets that differ only in numbers
  // read the same keys) and from the probes: about 2 s in Release.
  const auto keys = collect_keys(LBDEM_SOURCE_DIR);
  std::vector<std::string> undocumented;
  const std::string md = reference_markdown(keys, undocumented);
  {
    INFO(
        "keys read by a preset or probe without a unit and meaning in "
        "scenarios/config_reference.cpp");
    for (const auto& k : undocumented) CHECK(k == "");
  }
  {
    INFO(
        "patterns in scenarios/config_reference.cpp that no key read by a preset or probe falls "
        "under: a key nothing reads, or one to set in a probe (scenarios/config_reference/)");
    for (const auto& p : unread_docs(keys)) CHECK(p == "");
  }
  // Keys every scenario reads, some only one does, and some only the probes set: the collection
  // reached all readers, in each form of an input that has several.
  for (const char* k : {"scenario",
                        "run.end_time",
                        "dem.dt",
                        "contact.normal",
                        "fluid.dx",
                        "coupling.drag",
                        "rheometer.fill_mass",
                        "jet_mill.nozzles.angle_deg",
                        "bed.height_fraction",
                        "fill.radius.kind",
                        "particles.radius.kind",
                        "walls.kind",
                        "walls.file",
                        "particle.position",
                        "outlet.check_every",
                        "fluid.faces.x_lo",
                        "fluid.faces.x_lo.kind",
                        "fluid.faces.x_lo.slip_length",
                        "fluid.faces.z_hi.velocity",
                        "fluid.faces.y_hi.ramp_from",
                        "fluid.faces.z_lo.pressure",
                        "jet_mill.feed.speed",
                        "jet_mill.feed.supply_pressure",
                        "jet_mill.classifier.radius",
                        "jet_mill.chamber_stl",
                        "coarse_grain.particles_per_parcel",
                        "particles.radius.sigma"}) {
    CAPTURE(k);
    CHECK(keys.count(k) == 1);
  }
  // Every face takes every key of each kind in every scenario that reads it.
  for (const char* face : {"x_lo", "x_hi", "y_lo", "y_hi", "z_lo", "z_hi"})
    for (const char* key : {"", ".kind", ".slip_length", ".velocity", ".ramp_start", ".ramp_time",
                            ".ramp_from", ".pressure", ".backflow"}) {
      const std::string path = std::string("fluid.faces.") + face + key;
      CAPTURE(path);
      REQUIRE(keys.count(path) == 1);
      CHECK(keys.at(path).scenarios.count("box") == 1);
    }
  std::ifstream in(std::string(LBDEM_SOURCE_DIR) + "/docs/config.md");
  std::stringstream committed;
  committed << in.rdbuf();
  INFO("regenerate: ./build/bin/lbdem-cli config > docs/config.md");
  CHECK(committed.str() == md);
}

TEST_CASE("config reference: each getter records type, default, range and choices", "[scenarios]") {
  const Config c = Config::from_string("[a]\nx = 2.0\nname = \"q\"\n");
  const Config a = c.section("a");
  a.get("x", 1.5, Range::positive());
  a.get_int("n", 3, Range::closed(1, 512));
  a.get_choice("name", "p", {"p", "q"});
  a.get_vec3("v", Vec3(0, 0, -9.81));
  const auto& k = c.read_keys();
  CHECK(k.at("a.x").type == "number");
  CHECK(k.at("a.x").default_text == "1.5");
  CHECK(k.at("a.x").range_text == "> 0");
  CHECK(k.at("a.n").range_text == ">= 1 and <= 512");
  CHECK(k.at("a.name").choices == std::vector<std::string>{"p", "q"});
  CHECK(k.at("a.v").default_text == "[0, 0, -9.81]");
  a.require("x");
  CHECK(k.at("a.x").required);
}

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
  // read the same keys): about 2 s in Release.
  const auto keys = collect_keys(LBDEM_SOURCE_DIR);
  std::vector<std::string> undocumented;
  const std::string md = reference_markdown(keys, undocumented);
  INFO("keys read by a preset without a unit and meaning in scenarios/config_reference.cpp");
  for (const auto& k : undocumented) CHECK(k == "");
  // Keys every scenario reads, and some only one does: the collection reached all readers.
  for (const char* k : {"scenario", "run.end_time", "dem.dt", "contact.normal", "fluid.dx",
                        "coupling.drag", "rheometer.fill_mass", "jet_mill.nozzles.angle_deg",
                        "bed.height_fraction", "fill.radius.kind", "particles.radius.kind"}) {
    CAPTURE(k);
    CHECK(keys.count(k) == 1);
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

// core/config: the fix an unknown key gets, and values in errors printed as the user wrote them.
#include <catch2/catch.hpp>

#include "core/config.hpp"
#include "core/error.hpp"

#include <functional>

using namespace lbdem;
using Catch::Matchers::Contains;

namespace {
const std::set<std::string> kKnown = {"dem.dt",         "dem.skin",        "dem.impact_speed",
                                      "fluid.dx",       "fluid.viscosity", "fluid.faces.z_lo.kind",
                                      "run.end_time",   "run.seed",        "materials.density",
                                      "output.interval"};

std::string error_of(const std::string& toml, const std::function<void(const Config&)>& read) {
  try {
    const Config c = Config::from_string(toml);
    read(c);
    c.check_unknown_keys();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("an unknown key is matched within its own table first", "[core][config]") {
  // A misspelling (two edits) in its table.
  CHECK(unknown_key_fix("dem.sikn", kKnown) == "did you mean 'dem.skin'? (or remove it)");
  // The right name in the wrong table, or in a misspelt one.
  CHECK(unknown_key_fix("dem.viscosity", kKnown) ==
        "did you mean 'fluid.viscosity'? (or remove it)");
  CHECK(unknown_key_fix("flud.dx", kKnown) == "did you mean 'fluid.dx'? (or remove it)");
  // Table and name both misspelt: the whole path, if it is near (a quarter of its length).
  CHECK(unknown_key_fix("flud.dxx", kKnown) == "did you mean 'fluid.dx'? (or remove it)");
  // Nothing near: the table's keys, rather than whatever path of another table is nearest.
  CHECK(unknown_key_fix("dem.xyzzy", kKnown) ==
        "remove it (the keys read from [dem] are dt, impact_speed, skin)");
  CHECK(unknown_key_fix("nothing.like.it", kKnown) == "remove it");
  // In an array of tables the suggestion keeps the index written.
  CHECK(unknown_key_fix("materials[1].densty", kKnown) ==
        "did you mean 'materials[1].density'? (or remove it)");
}

TEST_CASE("values in input errors read as written, not at 17 digits", "[core][config]") {
  // toml++ prints 0.1 as 0.10000000000000001; the error shows what the user typed.
  CHECK_THAT(error_of("[a]\nx = [0.1, 0.2]\n", [](const Config& c) { c.get("a.x", 1.0); }),
             Contains("= [0.1, 0.2]"));
  // A value just past a limit is not rounded onto it ("1.0000001 must be <= 1", not "1 must be").
  CHECK_THAT(error_of("[a]\nx = 1.0000001\n",
                      [](const Config& c) { c.get("a.x", 0.5, Range::closed(0, 1)); }),
             Contains("1.0000001"));
  CHECK_THAT(error_of("[a]\nx = 0.3\ny = 2\n", [](const Config& c) { c.get("a.y", 1.0); }),
             Contains("'a.x' = 0.3: unknown key"));
}

// core/config: the fix an unknown key gets, values in errors printed as the user wrote them, and
// presets based on others.
#include <catch2/catch.hpp>

#include "core/config.hpp"
#include "core/error.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
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
  // ... and so does a misspelt table's, but not another table's.
  CHECK(unknown_key_fix("materails[1].density", kKnown) ==
        "did you mean 'materials[1].density'? (or remove it)");
  CHECK(unknown_key_fix("materials[1].viscosity", kKnown) ==
        "did you mean 'fluid.viscosity'? (or remove it)");
  // A name known in another entry of the same array (a lognormal fill's sigma in a fixed one) is
  // not suggested as itself.
  CHECK(unknown_key_fix("materials[1].density", kKnown) ==
        "remove it (other entries read it, not materials[1]: its other settings do not use it)");
  // The same name in several tables: all of them.
  CHECK(unknown_key_fix("dem.density", {"fluid.density", "materials.density", "dem.dt"}) ==
        "did you mean 'fluid.density' or 'materials.density'? (or remove it)");
  // A one-letter name is not a misspelling of a two-letter one ("e" for "dt").
  CHECK(unknown_key_fix("dem.e", kKnown) ==
        "remove it (the keys read from [dem] are dt, impact_speed, skin)");
  CHECK(unknown_key_fix("dem.st", kKnown) == "did you mean 'dem.dt'? (or remove it)");
}

TEST_CASE("a --set path names the part that cannot hold the key", "[core][config]") {
  const auto set_error = [](const std::string& toml, const std::string& assignment) {
    try {
      Config::from_string(toml).set_override(assignment);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string doc = "[a]\nkind = \"wall\"\nlo = [0.0, 1.0]\n[[m]]\nx = 1.0\n";
  CHECK_THAT(set_error(doc, "a.kind.speed=1"),
             Contains("'a.kind' = \"wall\": holds a value, not a table"));
  CHECK_THAT(set_error(doc, "a.lo.x=1"), Contains("'a.lo' = [0, 1]: holds a value"));
  CHECK_THAT(set_error(doc, "m[2].x=1"),
             Contains("'m': has 1 entry, so m[2] is none of them; fix: use an index below 1"));
  CHECK_THAT(set_error(doc, "a[0].kind=1"), Contains("'a' = {kind = \"wall\", lo = [0, 1]}"));
  CHECK_THAT(set_error(doc, "q[0].x=1"), Contains("'q': is not in the config"));
  CHECK_THAT(set_error(doc, "m[one].x=1"), Contains("index [one] is not a whole number"));
  CHECK_THAT(set_error(doc, "m[0]=1"), Contains("cannot place this key"));
  CHECK_THAT(set_error(doc, " . =1"), Contains("names no key"));
  CHECK(set_error(doc, "m[0].x=2").empty());
  CHECK(set_error(doc, "b.c.d=2").empty());  // new tables are made as needed
}

TEST_CASE("a table in an error prints inline on its one line", "[core][config]") {
  // [materials] where [[materials]] belongs: toml++ would print the table as multi-line TOML.
  const std::string e =
      error_of("[m]\nname = \"a\\nb\"\nx = 0.1\n", [](const Config& c) { c.table_array("m"); });
  CHECK_THAT(e, Contains("'m' = {name = \"a\\nb\", x = 0.1}: expected an array of tables"));
  CHECK(e.find('\n') == std::string::npos);
}

TEST_CASE("a value that is not finite, with no range given, gets a fix", "[core][config]") {
  // The default range only asks for a finite number; its fix must not point at a range
  // ("give a value in that range") that the message does not state. (A key with a fix of its
  // own, coarse_grain.size_factor, is checked through the executable in test_box_cli.)
  CHECK_THAT(error_of("[a]\nx = nan\n", [](const Config& c) { c.get("a.x", 1.0); }),
             Contains("'a.x' = nan: must be finite; fix: give a finite number"));
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

namespace {

// Writes `text` to DIR/name and returns the path.
std::string write_preset(const std::filesystem::path& dir, const std::string& name,
                         const std::string& text) {
  std::filesystem::create_directories((dir / name).parent_path());
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

}  // namespace

TEST_CASE("a preset based on another takes its keys and overrides them key by key",
          "[core][config]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("lbdem_base_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  write_preset(dir, "series/cg1.toml",
               "scenario = \"box\"\n[run]\nend_time = 1.0\nseed = 3\n"
               "[fluid]\ndx = 2e-4\nfaces = { z_lo = \"wall\" }\n"
               "[[fill]]\nmass = 1.0\n[[fill]]\nmass = 2.0\n");
  // Relative to the file that names it; a base of a base; tables merge, values and arrays of
  // tables replace.
  write_preset(dir, "series/cg2.toml", "base = \"cg1.toml\"\n[fluid]\ndx = 4e-4\n");
  const std::string cg2_fixed =
      write_preset(dir, "cg2_fixed.toml",
                   "base = \"series/cg2.toml\"\n[run]\nend_time = 2.0\n[[fill]]\nmass = 5.0\n");
  const Config c = Config::from_file(cg2_fixed);
  CHECK(c.get_string("scenario", "") == "box");
  CHECK(c.section("run").get("end_time", 0.0) == 2.0);
  CHECK(c.section("run").get_int("seed", 0) == 3);
  CHECK(c.section("fluid").get("dx", 0.0) == 4e-4);
  CHECK(c.section("fluid").section("faces").get_string("z_lo", "") == "wall");
  REQUIRE(c.table_array("fill").size() == 1);
  CHECK(c.table_array("fill")[0].get("mass", 0.0) == 5.0);
  // The resolved config (a run folder's config.toml) names no base: it stands alone.
  CHECK(c.resolved_toml().find("base") == std::string::npos);
  CHECK_NOTHROW(c.check_unknown_keys());

  // A base that is missing, or that leads back to the file, is refused naming the key.
  const std::string missing = write_preset(dir, "missing.toml", "base = \"none.toml\"\n");
  try {
    (void)Config::from_file(missing);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.key() == "base");
  }
  write_preset(dir, "a.toml", "base = \"b.toml\"\n");
  const std::string b = write_preset(dir, "b.toml", "base = \"a.toml\"\n");
  try {
    (void)Config::from_file(b);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.key() == "base");
    CHECK(std::string(e.what()).find("leads back") != std::string::npos);
  }
  fs::remove_all(dir);
}

#include "run/run_manifest.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/h5.hpp"

namespace lbdem::run {

double RunManifest::number(const std::string& name) const {
  for (const auto& d : derived)
    if (d.name == name) return d.value;
  return std::nan("");
}

void write_run_manifest(const std::string& dir, const RunManifest& m) {
  toml::table run{{"scenario", m.scenario},       {"lbdem_version", m.version},
                  {"config_hash", m.config_hash}, {"time_s", m.time_s},
                  {"end_time_s", m.end_time_s},   {"complete", m.complete}};
  // A banner row may repeat a name (one per material, say): the first is kept, as it was printed
  // first.
  toml::table derived, units;
  for (const auto& d : m.derived)
    if (derived.insert(d.name, d.value).second) units.insert(d.name, d.unit);
  toml::table root{
      {"run", std::move(run)}, {"derived", std::move(derived)}, {"units", std::move(units)}};
  if (m.cost) {
    toml::table phases;
    for (const auto& [name, sec] : m.cost->phases) phases.insert(name, sec);
    root.insert("cost", toml::table{{"from_s", m.cost->from_s},
                                    {"to_s", m.cost->to_s},
                                    {"wall_s", m.cost->wall_s},
                                    {"phase_s", std::move(phases)}});
  }
  std::ostringstream text;
  text << "# lbdem run manifest: the run's numbers for studies and tools (docs/user-guide.md,\n"
          "# Run folder). [derived]: the start-up banner's numbers in SI ([units] names them);\n"
          "# [cost]: wall seconds of the stepping loop and of each phase over every invocation,\n"
          "# from from_s to to_s.\n"
       << root << "\n";
  write_file_atomic(dir + "/" + kRunManifest, text.str());
}

std::optional<RunManifest> read_run_manifest(const std::string& dir) {
  const std::string path = dir + "/" + kRunManifest;
  if (!std::filesystem::exists(path)) return std::nullopt;
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(path + " does not parse: " + std::string(e.description()));
  }
  RunManifest m;
  m.scenario = t["run"]["scenario"].value_or(std::string());
  m.version = t["run"]["lbdem_version"].value_or(std::string());
  m.config_hash = t["run"]["config_hash"].value_or(std::int64_t(0));
  m.time_s = t["run"]["time_s"].value_or(0.0);
  m.end_time_s = t["run"]["end_time_s"].value_or(0.0);
  m.complete = t["run"]["complete"].value_or(false);
  if (const toml::table* d = t["derived"].as_table())
    for (const auto& [key, node] : *d) {
      const std::string name(key.str());
      m.derived.push_back(
          {name, node.value_or(std::nan("")), t["units"][name].value_or(std::string())});
    }
  if (const toml::table* c = t["cost"].as_table()) {
    RunCost cost;
    cost.from_s = (*c)["from_s"].value_or(0.0);
    cost.to_s = (*c)["to_s"].value_or(0.0);
    cost.wall_s = (*c)["wall_s"].value_or(0.0);
    if (const toml::table* ph = (*c)["phase_s"].as_table())
      for (const auto& [key, node] : *ph)
        cost.phases.emplace_back(std::string(key.str()), node.value_or(0.0));
    m.cost = cost;
  }
  return m;
}

}  // namespace lbdem::run

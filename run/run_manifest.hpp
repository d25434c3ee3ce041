#pragma once
// The run manifest, run.toml in every run folder: what studies and tools read about a run instead
// of its human-readable log. Written atomically with every checkpoint (and so at the run's end):
// the lbdem version, the resolved configuration's hash, how far the run has got, the numbers of
// the start-up banner (SI, as Log::derived printed them) and the cost sums of the checkpoint
// (run_cost.hpp: stepping wall time and phase seconds over every invocation).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/log.hpp"
#include "run/run_cost.hpp"

namespace lbdem::run {

inline constexpr const char* kRunManifest = "run.toml";

struct RunManifest {
  std::string scenario;
  std::string version;           // lbdem's
  std::int64_t config_hash = 0;  // RunIdentity::hash of the resolved configuration
  double time_s = 0;             // simulated time of the checkpoint written with it
  double end_time_s = 0;         // run.end_time
  bool complete = false;         // the run reached end_time_s
  std::vector<DerivedValue> derived;
  std::optional<RunCost> cost;

  /// The banner number of that name (its first row), NaN if the run printed none.
  double number(const std::string& name) const;
};

/// Writes DIR/run.toml atomically (temp + rename).
void write_run_manifest(const std::string& dir, const RunManifest& m);
/// DIR/run.toml, or nullopt if the folder has none (a run written before lbdem kept one);
/// throws std::runtime_error naming the file if it cannot be parsed.
std::optional<RunManifest> read_run_manifest(const std::string& dir);

}  // namespace lbdem::run

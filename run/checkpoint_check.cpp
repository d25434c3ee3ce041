#include "run/checkpoint_check.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/error.hpp"
#include "core/types.hpp"
#include "run/run_loop.hpp"

namespace lbdem::run {

namespace fs = std::filesystem;

namespace {

// Where a checkpoint keeps its identity (the group's attributes and datasets).
constexpr const char* kRunGroup = "/run";

std::string lattice_text(const std::array<std::int64_t, 3>& n) {
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return "no gas lattice";
  return "a gas lattice of " + std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " +
         std::to_string(n[2]) + " cells";
}

// The checksum a checkpoint carried before every dataset had its own: FNV-1a over the bytes of
// the positions and velocities (/dem state_hash). Still verified in such checkpoints.
std::int64_t legacy_state_hash(const std::vector<Vec3>& x, const std::vector<Vec3>& v) {
  std::uint64_t h = 1469598103934665603ull;
  for (const auto* a : {&x, &v}) {
    const auto* b = reinterpret_cast<const unsigned char*>(a->data());
    for (std::size_t k = 0; k < a->size() * sizeof(Vec3); ++k) h = (h ^ b[k]) * 1099511628211ull;
  }
  std::int64_t out;
  std::memcpy(&out, &h, sizeof out);
  return out;
}

// A value in a one-line message: a long array is cut.
std::string shown(const std::string& v) {
  return v.size() > 60 ? v.substr(0, 56) + " ..." : v;
}

// "a = 1 there, 2 in config.toml; b = ...; and 2 more keys": the keys whose values differ.
std::string config_difference(const std::vector<std::pair<std::string, std::string>>& there,
                              const std::vector<std::pair<std::string, std::string>>& here) {
  std::map<std::string, std::pair<std::string, std::string>> keys;
  const std::string absent = "(absent)";
  for (const auto& [k, v] : there) keys[k] = {v, absent};
  for (const auto& [k, v] : here) {
    auto it = keys.find(k);
    if (it == keys.end())
      keys[k] = {absent, v};
    else
      it->second.second = v;
  }
  std::vector<std::string> diffs;
  for (const auto& [k, v] : keys)
    if (v.first != v.second)
      diffs.push_back(k + " = " + shown(v.first) + " there, " + shown(v.second) +
                      " in config.toml");
  std::string s;
  const std::size_t shown_keys = std::min<std::size_t>(diffs.size(), 3);
  for (std::size_t k = 0; k < shown_keys; ++k) s += (k ? "; " : "") + diffs[k];
  if (const std::size_t more = diffs.size() - shown_keys; more > 0)
    s += "; and " + std::to_string(more) + (more == 1 ? " more key" : " more keys");
  return s;
}

std::vector<std::pair<std::string, std::string>> parse_physics(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string line = text.substr(pos, end - pos);
    if (const auto eq = line.find(" = "); eq != std::string::npos)
      out.emplace_back(line.substr(0, eq), line.substr(eq + 3));
    pos = end + 1;
  }
  return out;
}

std::string read_status(const std::string& dir) {
  std::ifstream f(dir + "/status");
  std::string s;
  std::getline(f, s);
  return s;
}

// Lines of a text file (0 if it cannot be read).
long count_lines(const std::string& path) {
  std::ifstream f(path);
  long n = 0;
  for (std::string line; std::getline(f, line);) ++n;
  return n;
}

}  // namespace

std::string RunIdentity::physics_text() const {
  std::string s;
  for (const auto& [k, v] : physics) s += k + " = " + v + "\n";
  return s;
}

std::int64_t RunIdentity::hash() const {
  const std::string text = "scenario = " + scenario + "\n" + physics_text();
  const std::uint64_t h = checksum64(text.data(), text.size());
  std::int64_t out;
  std::memcpy(&out, &h, sizeof out);
  return out;
}

bool is_verified_key(const std::string& key) {
  if (key == "scenario" || key == "run.end_time" || key == "run.phase_timers") return false;
  if (key == "output.collisions.grid_cells") return true;
  return key.rfind("output.", 0) != 0;
}

RunIdentity run_identity(const std::string& scenario, const Config& cfg,
                         const std::array<std::int64_t, 3>& lattice) {
  RunIdentity id;
  id.scenario = scenario;
  id.lattice = lattice;
  for (auto& kv : cfg.resolved_values())
    if (is_verified_key(kv.first)) id.physics.push_back(std::move(kv));
  return id;
}

void save_identity(H5Out& f, const RunIdentity& id, std::int64_t particles, double final_end_time) {
  f.group(kRunGroup);
  f.attr("scenario", id.scenario, kRunGroup);
  f.attr("config_hash", id.hash(), kRunGroup);
  f.attr("particles", particles, kRunGroup);
  if (final_end_time > 0) f.attr("final_end_time_s", final_end_time, kRunGroup);
  const std::string text = id.physics_text();
  f.write(std::string(kRunGroup) + "/physics_config",
          std::vector<std::uint8_t>(text.begin(), text.end()));
  f.write(std::string(kRunGroup) + "/lattice",
          std::vector<std::int64_t>(id.lattice.begin(), id.lattice.end()));
}

std::optional<std::string> checkpoint_fault(const std::string& file) {
  try {
    if (!fs::exists(file)) return "missing";
    const H5In f(file);
    if (!f.has_attr("format") || f.attr_string("format") != kCheckpointFormat)
      return "not an lbdem checkpoint";
    if (f.has_checksums()) {
      if (auto fault = f.checksum_fault()) return fault;
      if (f.has_attr("particles", kRunGroup) && f.has("/dem")) {
        const auto n = f.attr_int("particles", kRunGroup);
        const auto x = f.vec3s("/dem/x");
        if (std::int64_t(x.size()) != n)
          return "it records " + std::to_string(n) + " particles and holds " +
                 std::to_string(x.size()) + " positions";
      }
      return std::nullopt;
    }
    if (!f.has_attr("state_hash", "/dem")) return std::nullopt;
    const auto x = f.vec3s("/dem/x"), v = f.vec3s("/dem/v");
    if (x.size() != v.size()) return "positions and velocities differ in count";
    if (legacy_state_hash(x, v) != f.attr_int("state_hash", "/dem"))
      return "the positions and velocities fail their checksum";
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string(e.what());
  }
}

double checkpoint_time(const H5In& f) {
  return f.has_attr("time_s") ? f.attr_double("time_s") : f.attr_double("time_s", "/dem");
}

ResumePoint check_resume(const std::string& dir, const RunIdentity& id, double end_time) {
  const auto refuse = [&](const std::string& problem, const std::string& fix) {
    return InputError("--resume", dir, problem, fix);
  };
  const std::string fresh = "start a new run from it (--config " + dir + "/config.toml --out NEW)";
  ResumePoint p;
  // The newest generation whose data verifies.
  p.checkpoint = dir + "/checkpoint.h5";
  std::string name = "checkpoint.h5";
  if (const auto fault = checkpoint_fault(p.checkpoint)) {
    const std::string prev = dir + "/" + kPreviousCheckpoint;
    if (const auto older = checkpoint_fault(prev))
      throw refuse("no checkpoint verifies: checkpoint.h5 (" + *fault + "), " +
                       kPreviousCheckpoint + " (" + *older + ")",
                   "start the run anew");
    p.warnings.push_back("warning: checkpoint.h5 does not verify (" + *fault + "); resuming from " +
                         kPreviousCheckpoint + ", the generation before");
    p.checkpoint = prev;
    name = kPreviousCheckpoint;
  }
  const H5In f(p.checkpoint);
  // The DEM state's layout: a checkpoint of an lbdem whose contact records had another shape is
  // refused here, before anything is written. A run without particles has no DEM state.
  const bool particles = f.has("/dem");
  if (particles)
    if (const std::int64_t layout = f.attr_int("layout_version", "/dem");
        layout != dem::DemSolver::kCheckpointLayout)
      throw refuse(name + " holds the DEM state in layout " + std::to_string(layout) +
                       ", this lbdem reads layout " +
                       std::to_string(dem::DemSolver::kCheckpointLayout) +
                       " (it was written by another lbdem build)",
                   "finish the run with the lbdem that began it, or " + fresh);
  p.time_s = checkpoint_time(f);
  // Its origin: scenario, physics, lattice.
  if (!f.has_attr("config_hash", kRunGroup)) {
    p.warnings.push_back("warning: " + name +
                         " records no config (written before lbdem verified resumes): the "
                         "config could not be verified against it; resuming as it is");
  } else {
    if (const std::string s = f.attr_string("scenario", kRunGroup); s != id.scenario)
      throw refuse(name + " is from a " + s + " run and this folder's config.toml is for " +
                       id.scenario + " (a checkpoint copied in from another run?)",
                   "put back this run's own checkpoint, or resume the folder it came from");
    if (f.attr_int("config_hash", kRunGroup) != id.hash()) {
      const auto raw = f.uint8s(std::string(kRunGroup) + "/physics_config");
      const std::string diff =
          config_difference(parse_physics(std::string(raw.begin(), raw.end())), id.physics);
      throw refuse(name + " was written under other physics: " +
                       (diff.empty() ? std::string("its config hash differs") : diff),
                   "put the values back in config.toml (a resume may change only run.end_time "
                   "and output.*), or " +
                       fresh);
    }
    const auto n = f.int64s(std::string(kRunGroup) + "/lattice");
    const std::array<std::int64_t, 3> lattice = {n.size() > 0 ? n[0] : -1, n.size() > 1 ? n[1] : -1,
                                                 n.size() > 2 ? n[2] : -1};
    if (lattice != id.lattice)
      throw refuse(name + " holds " + lattice_text(lattice) + " and this run's config makes " +
                       lattice_text(id.lattice),
                   "put back this run's own checkpoint, or resume the folder it came from");
  }
  // A finished run that run.end_time does not extend: nothing to do, nothing to check further.
  if (f.has_attr("final_end_time_s", kRunGroup) && read_status(dir) == "finished") {
    p.finished_end_time = f.attr_double("final_end_time_s", kRunGroup);
    if (end_time <= p.finished_end_time) {
      p.finished = true;
      return p;
    }
  }
  // What the resume appends to or rewrites from must all be there, or it would fail after
  // writing a checkpoint that then cannot be resumed either.
  const std::string restore = "put the file back as the run left it, or " + fresh;
  const long rows = static_cast<long>(f.attr_int("timeseries_rows"));
  if (!fs::exists(dir + "/timeseries.csv"))
    throw refuse("timeseries.csv is missing (the resume keeps its first " + std::to_string(rows) +
                     " rows and appends)",
                 restore);
  if (const long lines = count_lines(dir + "/timeseries.csv"); lines < rows + 1)
    throw refuse("timeseries.csv holds " + std::to_string(std::max(0L, lines - 1)) +
                     " rows, the checkpoint counts " + std::to_string(rows),
                 restore);
  const std::size_t snapshots = f.doubles("/snapshot_times_s").size();
  const bool gas = f.has("/fluid");
  for (std::size_t k = 0; k < snapshots; ++k)
    for (const char* kind : {"particles", "fluid"}) {
      if ((std::string(kind) == "fluid" && !gas) ||
          (std::string(kind) == "particles" && !particles))
        continue;
      char file[64];
      std::snprintf(file, sizeof file, "snapshots/%s_%06zu.h5", kind, k);
      if (!fs::exists(dir + "/" + file))
        throw refuse(std::string(file) + " is missing (the checkpoint counts " +
                         std::to_string(snapshots) + (snapshots == 1 ? " snapshot" : " snapshots") +
                         ", which the resume links into " + kind + ".h5 and " + kind +
                         ".xdmf again)",
                     restore);
    }
  return p;
}

}  // namespace lbdem::run

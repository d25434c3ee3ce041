#pragma once
// What a checkpoint must prove before a run resumes from it (docs/user-guide.md, Resuming a run).
// Its data: every dataset carries a checksum (H5Out::checksum_datasets), and the particle count
// it records matches its positions. Its origin: the scenario, the physics part of the resolved
// config (all but the keys is_verified_key leaves out, as key = value lines, so that a refusal
// names the keys that differ, and their hash) and the gas lattice. A resume of a folder whose
// config.toml was edited to other physics, or into which another run's checkpoint was copied, is
// refused before anything is written, as is one whose outputs to append to are gone; a finished
// run whose run.end_time was not raised is left as it is.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/config.hpp"
#include "core/h5.hpp"

namespace lbdem::run {

/// The checkpoint format this lbdem writes (and the one before checksums and identity, which
/// shares the name: those checkpoints are recognised by what they lack).
inline constexpr const char* kCheckpointFormat = "lbdem-checkpoint-1";

/// The run a checkpoint belongs to.
struct RunIdentity {
  std::string scenario;
  /// {key, value} of every verified key of the resolved config, in key order.
  std::vector<std::pair<std::string, std::string>> physics;
  std::array<std::int64_t, 3> lattice{};  // gas cells per axis; zeros without gas
  /// The physics lines as text, "key = value\n" each.
  std::string physics_text() const;
  std::int64_t hash() const;
};

/// False for the keys a resume may change: run.end_time (how far to run), output.* (what is
/// written and how often) and run.phase_timers (timing only), but not
/// output.collisions.grid_cells, whose grid the checkpoint's collision statistics are laid out
/// on; the top-level `scenario` is checked as such.
bool is_verified_key(const std::string& key);

RunIdentity run_identity(const std::string& scenario, const Config& cfg,
                         const std::array<std::int64_t, 3>& lattice);

/// Records `id` and the particle count in a checkpoint being written; `final_end_time` > 0 marks
/// the checkpoint written at the end of a run to that run.end_time.
void save_identity(H5Out& f, const RunIdentity& id, std::int64_t particles, double final_end_time);

/// nullopt if `file` opens as a checkpoint whose data verifies (every dataset against its
/// checksum, the recorded particle count against the positions; a checkpoint with one checksum
/// over positions and velocities by that; one with none as it is); else what is wrong.
std::optional<std::string> checkpoint_fault(const std::string& file);

/// The simulated time a checkpoint stands at [s]: the loop's clock (time_s), or, in a checkpoint
/// written before the loop kept it, the DEM's.
double checkpoint_time(const H5In& f);

struct ResumePoint {
  std::string checkpoint;             // the generation to resume from
  std::vector<std::string> warnings;  // for log.txt, once it is open
  bool finished = false;              // nothing to do: the run ended at end_time or later
  double time_s = 0;                  // the checkpoint's simulated time
  double finished_end_time = 0;       // the run.end_time the finished run ran to
};

/// Chooses and verifies the checkpoint to resume the run folder `dir` from, given the identity
/// its config.toml resolves to and its run.end_time. Reads only. Throws InputError (key
/// --resume, one line naming what differs and the fix) when no generation's data verifies, when
/// the newest that does is from another scenario, config or lattice, or when a file that the
/// resume appends to or rewrites from (timeseries.csv, the snapshots) is missing.
ResumePoint check_resume(const std::string& dir, const RunIdentity& id, double end_time);

}  // namespace lbdem::run

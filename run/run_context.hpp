#pragma once
// What a scenario needs from the executable: where to write, whether it resumes, threads, the log.
#include <string>

#include "core/log.hpp"

namespace lbdem::run {

struct RunIdentity;

struct RunContext {
  std::string dir;      // run folder (exists)
  bool resume = false;  // continue from dir/checkpoint.h5
  int threads = 1;
  Log* log = nullptr;
  bool plots = true;  // make PNG plots at the end
  /// Resume: the checkpoint generation check_resume chose (checkpoint_check.hpp); empty: dir's
  /// checkpoint.h5.
  std::string checkpoint;
  /// Recorded in every checkpoint, for a resume to verify against; none: not recorded.
  const RunIdentity* identity = nullptr;
};

}  // namespace lbdem::run

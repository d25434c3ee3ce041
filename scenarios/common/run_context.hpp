#pragma once
// What a scenario needs from the executable: where to write, whether it resumes, threads, the log.
#include <string>

#include "core/log.hpp"

namespace lbdem::scenarios {

struct RunContext {
  std::string dir;      // run folder (exists)
  bool resume = false;  // continue from dir/checkpoint.h5
  int threads = 1;
  Log* log = nullptr;
  bool plots = true;  // make PNG plots at the end
};

}  // namespace lbdem::scenarios

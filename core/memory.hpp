#pragma once
// The process's memory as the kernel counts it (Linux /proc/self/status): resident set now
// (VmRSS) and its peak (VmHWM). The benchmarks report bytes per particle and per cell from it;
// elsewhere both read 0.
#include <cstddef>

namespace lbdem {

struct MemoryUse {
  std::size_t resident = 0;  // [B] pages in RAM now
  std::size_t peak = 0;      // [B] largest resident set so far
};

MemoryUse memory_use();

}  // namespace lbdem

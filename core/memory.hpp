#pragma once
// The process's memory as the kernel counts it (Linux /proc/self/status): resident set now
// (VmRSS) and its peak (VmHWM). The benchmarks report bytes per particle and per cell from it;
// elsewhere both read 0. And the memory a new allocation can take (/proc/meminfo MemAvailable),
// against which a run's estimate is checked before it allocates.
#include <cstddef>
#include <string>

namespace lbdem {

struct MemoryUse {
  std::size_t resident = 0;  // [B] pages in RAM now
  std::size_t peak = 0;      // [B] largest resident set so far
};

MemoryUse memory_use();

/// MemAvailable of /proc/meminfo [B]: what new allocations can take without swapping; 0 where
/// the kernel does not say (then nothing is checked).
std::size_t memory_available();

/// A size in bytes for a message: "3.2 GB (3.2e+09 B)".
std::string bytes_text(double bytes);

/// Throws InputError naming `key` = `value` when `bytes` (the estimate of what `what` will
/// allocate) exceed memory_available(), with the estimate, what is free and `fix`.
void require_memory(double bytes, const std::string& what, const std::string& key,
                    const std::string& value, const std::string& fix);

}  // namespace lbdem

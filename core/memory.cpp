#include "core/memory.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace lbdem {

MemoryUse memory_use() {
  MemoryUse m;
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    std::size_t kib = 0;
    if (!(s >> key >> kib)) continue;
    if (key == "VmRSS:") m.resident = kib * 1024;
    if (key == "VmHWM:") m.peak = kib * 1024;
  }
  return m;
}

}  // namespace lbdem

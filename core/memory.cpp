#include "core/memory.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace lbdem {

namespace {
// The value of a "Key:  <n> kB" line of a /proc file [B]; 0 when absent.
std::size_t proc_kib(const char* file, const std::string& wanted) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    std::size_t kib = 0;
    if ((s >> key >> kib) && key == wanted) return kib * 1024;
  }
  return 0;
}
}  // namespace

MemoryUse memory_use() {
  return {proc_kib("/proc/self/status", "VmRSS:"), proc_kib("/proc/self/status", "VmHWM:")};
}

std::size_t memory_available() {
  return proc_kib("/proc/meminfo", "MemAvailable:");
}

std::string bytes_text(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  double v = bytes;
  while (v >= 1000 && u < 6) v /= 1000, ++u;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g %s (%.3g B)", v, units[u], bytes);
  return buf;
}

void require_memory(double bytes, const std::string& what, const std::string& key,
                    const std::string& value, const std::string& fix) {
  const std::size_t free = memory_available();
  if (free == 0 || !(bytes > double(free))) return;
  throw InputError(key, value,
                   what + " need about " + bytes_text(bytes) + ", more than the " +
                       bytes_text(double(free)) + " this machine has available",
                   fix);
}

}  // namespace lbdem

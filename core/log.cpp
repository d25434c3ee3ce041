#include "core/log.hpp"

#include <cstdio>
#include <iostream>

namespace lbdem {

void Log::open(const std::string& path, bool append) {
  file_.open(path, append ? std::ios::app : std::ios::trunc);
  for (const auto& s : pending_) file_ << s << '\n';
  pending_.clear();
  file_.flush();
}

void Log::line(const std::string& s) {
  if (!quiet_) std::cout << s << '\n' << std::flush;
  if (file_.is_open()) {
    file_ << s << '\n';
    file_.flush();
  } else {
    pending_.push_back(s);
  }
}

void Log::derived(const std::string& name, double value, const std::string& unit,
                  const std::string& comment) {
  derived_.push_back({name, value, unit});
  char buf[256];
  std::snprintf(buf, sizeof buf, "  %-34s %14.6g %-8s %s", name.c_str(), value, unit.c_str(),
                comment.c_str());
  line(buf);
}

}  // namespace lbdem

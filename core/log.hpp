#pragma once
// Run log: every line goes to stdout and, once a run folder exists, to its log.txt.
#include <fstream>
#include <string>
#include <vector>

namespace lbdem {

class Log {
 public:
  /// Lines logged before open() are kept and written to the file when it opens.
  void open(const std::string& path, bool append);
  void line(const std::string& s);
  /// A "name = value unit  (comment)" row of the start-up banner.
  void derived(const std::string& name, double value, const std::string& unit,
               const std::string& comment = {});
  void set_quiet(bool q) { quiet_ = q; }

 private:
  std::ofstream file_;
  std::vector<std::string> pending_;
  bool quiet_ = false;
};

}  // namespace lbdem

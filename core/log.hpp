#pragma once
// Run log: every line goes to stdout and, once a run folder exists, to its log.txt.
#include <fstream>
#include <string>
#include <vector>

namespace lbdem {

/// One number of the start-up banner, as Log::derived printed it (SI).
struct DerivedValue {
  std::string name;
  double value;
  std::string unit;
};

class Log {
 public:
  /// Lines logged before open() are kept and written to the file when it opens.
  void open(const std::string& path, bool append);
  void line(const std::string& s);
  /// A "name = value unit  (comment)" row of the start-up banner.
  void derived(const std::string& name, double value, const std::string& unit,
               const std::string& comment = {});
  void set_quiet(bool q) { quiet_ = q; }
  /// Every derived() row so far, in order: the run manifest's numbers (run_manifest.hpp).
  const std::vector<DerivedValue>& derived_values() const { return derived_; }

 private:
  std::vector<DerivedValue> derived_;
  std::ofstream file_;
  std::vector<std::string> pending_;
  bool quiet_ = false;
};

}  // namespace lbdem

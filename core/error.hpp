#pragma once
// Input errors: one line naming the key, the value and the fix; the executables map them to exit 2.
#include <charconv>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace lbdem {

/// A file that could not be written, with the operating system's reason: "cannot write PATH: No
/// space left on device". write_error() builds it from errno.
class WriteError : public std::runtime_error {
 public:
  WriteError(std::string path, std::string reason, bool disk_full)
      : std::runtime_error("cannot write " + path + ": " + reason),
        path_(std::move(path)),
        disk_full_(disk_full) {}
  const std::string& path() const { return path_; }
  bool disk_full() const { return disk_full_; }

 private:
  std::string path_;
  bool disk_full_;
};

/// The WriteError for `path` from an errno captured right after the failing call; where the
/// library that failed left errno 0 (HDF5 may), a file system with no blocks left counts as full.
WriteError write_error(const std::string& path, int err);

class InputError : public std::runtime_error {
 public:
  InputError(std::string key, std::string value, std::string problem, std::string fix)
      : std::runtime_error(format(key, value, problem, fix)),
        key_(std::move(key)),
        value_(std::move(value)),
        problem_(std::move(problem)),
        fix_(std::move(fix)) {}
  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }
  /// The same error with another fix (a caller that knows which changes pass its checks).
  InputError with_fix(std::string fix) const { return {key_, value_, problem_, std::move(fix)}; }

  static std::string format(const std::string& key, const std::string& value,
                            const std::string& problem, const std::string& fix) {
    std::string s = "'" + key + "'";
    // A value echoed whole would not be one line: an array of 100,000 numbers given for a vector
    // is shown by its start and its length (paths and ordinary values fit).
    constexpr std::size_t kShown = 200;
    if (value.size() > kShown)
      s += " = " + value.substr(0, kShown - 40) + " ... (" + std::to_string(value.size()) +
           " characters)";
    else if (!value.empty())
      s += " = " + value;
    s += ": " + problem;
    if (!fix.empty()) s += "; fix: " + fix;
    return s;
  }

 private:
  std::string key_, value_, problem_, fix_;
};

/// Renders a number the way a user would type it in a TOML file.
inline std::string to_text(double v, int digits = 6) {
  std::ostringstream os;
  os.precision(digits);
  os << v;
  return os.str();
}

/// A value the user gave, as the shortest text that reads back as it: 0.1 stays 0.1 (toml++ prints
/// 17 digits), and a value just past a limit does not print as the limit (1.0000001 against "<= 1"
/// reads "1" at 6 digits).
inline std::string shortest_text(double v) {
  char buf[32];  // the longest double is 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// Renders a list of numbers as TOML writes it: [a, b, c].
inline std::string list_text(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + to_text(v[i]);
  return s + "]";
}

/// A 3-vector (anything indexable by 0-2) as list_text writes it: [x, y, z].
template <class V>
std::string vec_text(const V& v) {
  return list_text({double(v[0]), double(v[1]), double(v[2])});
}

/// Exit code for every input error (docs/user-guide.md, Troubleshooting).
inline constexpr int kInputErrorExit = 2;

}  // namespace lbdem

#pragma once
// Running the real executable from a test: exit code and stderr of `lbdem-cli ARGS --no-plots`,
// and a fresh scratch folder per test process.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace lbdem::test {

struct CliResult {
  int code;
  std::string err;
};

inline std::string read_text(const std::string& path) {
  std::ifstream f(path);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

inline CliResult cli(const std::string& args) {
  namespace fs = std::filesystem;
  static int calls = 0;  // unique per process and call: ctest runs test processes side by side
  const std::string errfile =
      fs::temp_directory_path() /
      ("lbdem_cli_err_" + std::to_string(::getpid()) + "_" + std::to_string(calls++));
  const std::string cmd =
      std::string(LBDEM_CLI) + " " + args + " --no-plots > /dev/null 2> " + errfile;
  const int rc = std::system(cmd.c_str());
  std::string err = read_text(errfile);
  fs::remove(errfile);
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, err};
}

/// `--set` arguments that fill the default box with `count` beads near its floor (the box's
/// preset otherwise): a run of a few ms that the CLI tests resume, stop and refuse.
inline std::string beads_near_floor(int count) {
  return " --set fill[0].count=" + std::to_string(count) +
         " --set 'fill[0].lo=[0.0,0.0,0.0]' --set 'fill[0].hi=[0.06,0.06,0.03]'";
}

/// An empty path under the temp folder, unique per test process.
inline std::string tmpdir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path p =
      fs::temp_directory_path() / ("lbdem_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p.string();
}

}  // namespace lbdem::test

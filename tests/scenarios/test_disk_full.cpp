// A disk that fills during a run (a tmpfs of 128 kB mounted in a private mount namespace, as an
// unprivileged user may with `unshare -rm`): the error names the file and the operating system's
// reason, status says "failed (disk full: ...)", no temp file is left, and the checkpoint written
// before the disk filled resumes, elsewhere, to the same result as a run that never failed.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <sys/wait.h>

#include "helpers/cli.hpp"
#include "helpers/resume_check.hpp"

namespace fs = std::filesystem;

TEST_CASE("a run on a full disk names ENOSPC and its checkpoint resumes elsewhere",
          "[scenarios][checkpoint]") {
  using lbdem::test::cli;
  using lbdem::test::read_text;
  using lbdem::test::tmpdir;
  if (std::system("unshare -rm true > /dev/null 2>&1") != 0) {
    WARN("skipped: this machine does not allow a private mount namespace (unshare -rm)");
    return;
  }
  const std::string mnt = tmpdir("full_mnt"), kept = tmpdir("full_kept"), err = kept + ".err",
                    full = tmpdir("full_ref");
  fs::create_directories(mnt);
  // 150 beads for 2 ms write about 240 kB; in 128 kB the start's snapshot and checkpoint fit and
  // a later snapshot does not. What the run left is copied out before the mount goes away.
  const std::string args = lbdem::test::beads_near_floor(150) + " --set run.end_time=0.002";
  const std::string inner = "mount -t tmpfs -o size=128k tmpfs " + mnt + " && " + LBDEM_CLI +
                            " run box --out " + mnt + "/run" + args +
                            " --no-plots > /dev/null 2> " + err + "; rc=$?; cp -a " + mnt +
                            "/run " + kept + "; exit $rc";
  const int rc = std::system(("unshare -rm sh -c '" + inner + "'").c_str());
  const std::string message = read_text(err), status = read_text(kept + "/status");
  INFO(message << "status: " << status);
  REQUIRE(WIFEXITED(rc));
  CHECK(WEXITSTATUS(rc) == 1);
  CHECK(message.find("cannot write " + mnt + "/run/") != std::string::npos);
  CHECK(message.find("No space left on device") != std::string::npos);
  CHECK(status.rfind("failed (disk full: cannot write", 0) == 0);
  CHECK(status.find("resume with") != std::string::npos);
  for (const auto& e : fs::recursive_directory_iterator(kept))
    CHECK(e.path().extension() != ".tmp");
  // Given room, the folder resumes from its checkpoint and ends as an uninterrupted run does.
  REQUIRE(fs::exists(kept + "/checkpoint.h5"));
  REQUIRE(cli("run box --out " + full + args).code == 0);
  REQUIRE(cli("run --resume " + kept).code == 0);
  lbdem::test::check_same_runs(full, kept, {"/dem/x", "/dem/v", "/dem/omega"});
  fs::remove_all(mnt);
  fs::remove_all(kept);
  fs::remove_all(full);
  fs::remove(err);
}

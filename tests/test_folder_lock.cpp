// app/output/folder_lock: one writer per output folder, and no lock file left.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <vector>

#include "app/output/folder_lock.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using elbowsim::FolderInUse;
using elbowsim::FolderLock;

TEST_CASE("folder lock: held, a second lock is refused; released, the lock file is gone") {
  const fs::path dir = elbowsim::testing::scratch("lock", "held") / "out";
  {
    const FolderLock held(dir);
    CHECK(fs::exists(dir / ".elbowsim.lock"));
    CHECK_THROWS_AS(FolderLock{dir},
                    FolderInUse);  // its own open file: refused as another process is
    std::ofstream(dir / "summary.json") << "{}";
  }
  CHECK_FALSE(fs::exists(dir / ".elbowsim.lock"));
  CHECK(fs::exists(dir / "summary.json"));
  const FolderLock again(dir);  // free again
  CHECK(fs::exists(dir / ".elbowsim.lock"));
}

TEST_CASE("folder lock: a folder it made and nothing was written to is removed") {
  const fs::path dir = elbowsim::testing::scratch("lock", "empty") / "out";
  { const FolderLock held(dir); }
  CHECK_FALSE(fs::exists(dir));
}

TEST_CASE("folder lock: never two holders while holders come and go, each removing the lock file") {
  // Four processes take and release the lock as fast as they can for 1.5 s;
  // a holder makes a marker file exclusively (O_EXCL) and removes it before
  // it lets go: a marker already there means two held the folder at once.
  // The race: a process opens the lock file, its holder removes it and lets
  // go, the process locks the removed file while a third creates and locks
  // a new one. FolderLock checks, once locked, that its file is still the one
  // at the path.
  const fs::path dir = elbowsim::testing::scratch("lock", "race");
  const fs::path marker = dir / "holder";
  std::vector<pid_t> children;
  for (int c = 0; c < 4; ++c) {
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      int held = 0;
      const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
      while (std::chrono::steady_clock::now() < end) {
        try {
          const FolderLock lock(dir);
          const int fd = ::open(marker.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0644);
          if (fd < 0) _exit(1);  // another holder's marker: two at once
          ::close(fd);
          ::unlink(marker.c_str());
          ++held;
        } catch (const FolderInUse&) {
        } catch (...) {
          _exit(2);
        }
      }
      _exit(held > 0 ? 0 : 3);
    }
    children.push_back(pid);
  }
  for (const pid_t pid : children) {
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    CAPTURE(status);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);  // 1: two holders at once; 2: an error; 3: never held
  }
  CHECK_FALSE(fs::exists(dir / ".elbowsim.lock"));
}

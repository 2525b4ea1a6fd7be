// One run at a time per output folder: two runs writing into the same folder
// would mix their files (rows of both in one trajectory.csv, a summary of one
// beside the trajectory of the other). A run holds an exclusive lock on
// <folder>/.elbowsim.lock (flock: released by the kernel when the process
// ends, however it ends) while it writes, and removes the file when done (a
// process killed outright leaves it, unlocked: the next run takes it).
#pragma once

#include <filesystem>
#include <stdexcept>

namespace elbowsim {

// Another process holds the folder.
class FolderInUse : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FolderLock {
 public:
  // Creates the folder if needed and takes its lock without waiting. Throws
  // FolderInUse when another process holds it, std::runtime_error when the
  // lock file cannot be opened (naming it). Released, it removes the lock
  // file, and a folder it created that is then empty (the run wrote
  // nothing: a full disk, a failed plan): the place is left as it was.
  explicit FolderLock(const std::filesystem::path& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
  std::filesystem::path folder_;
  bool created_ = false;  // the folder did not exist before
};

}  // namespace elbowsim

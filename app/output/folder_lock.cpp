#include "app/output/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace elbowsim {

namespace {

// Whether `fd` is still the file at `path`: the holder before us removes the
// lock file when it ends, so a lock taken on the file it removed (opened
// before the removal, locked after the holder let go) guards nothing.
bool still_at(int fd, const std::filesystem::path& path) {
  struct stat held = {}, there = {};
  return ::fstat(fd, &held) == 0 && ::stat(path.c_str(), &there) == 0 &&
         held.st_dev == there.st_dev && held.st_ino == there.st_ino;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& folder) : folder_(folder) {
  created_ = !std::filesystem::exists(folder);
  const std::filesystem::path file = folder / ".elbowsim.lock";
  // A few tries: each failed one saw another process end (its lock file
  // removed, or the empty folder it had made), never one still running.
  for (int attempt = 0; attempt < 1000; ++attempt) {
    std::filesystem::create_directories(folder);
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0 && errno == ENOENT) continue;  // the folder was removed meanwhile
    if (fd_ < 0)
      throw std::runtime_error("cannot open " + file.string() + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK)
        throw FolderInUse(folder.string() + " is in use by another elbowsim run (it holds " +
                          file.string() + "): wait for it to finish or write elsewhere (--out)");
      throw std::runtime_error("cannot lock " + file.string() + ": " + std::strerror(error));
    }
    if (still_at(fd_, file)) return;
    ::close(fd_);
    fd_ = -1;
  }
  throw std::runtime_error("cannot lock " + file.string() + ": it keeps being removed");
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  std::error_code ignored;
  // Removed while still held: a process that opened it meanwhile finds, once
  // it has the lock, that the file is gone, and starts again (still_at).
  std::filesystem::remove(folder_ / ".elbowsim.lock", ignored);
  if (created_ && std::filesystem::is_empty(folder_, ignored))
    std::filesystem::remove(folder_, ignored);  // (fails, harmlessly, if one was just made in it)
  ::close(fd_);  // closing releases the lock
}

}  // namespace elbowsim

#include "app/output/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace elbowsim {

FolderLock::FolderLock(const std::filesystem::path& folder) : folder_(folder) {
  created_ = !std::filesystem::exists(folder);
  std::filesystem::create_directories(folder);
  const std::filesystem::path file = folder / ".elbowsim.lock";
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open " + file.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw FolderInUse(folder.string() + " is in use by another elbowsim run (it holds " +
                        file.string() + "): wait for it to finish or write elsewhere (--out)");
    throw std::runtime_error("cannot lock " + file.string() + ": " + std::strerror(error));
  }
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  if (created_) {
    std::error_code ignored;
    bool only_lock = true;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, ignored))
      only_lock = only_lock && entry.path().filename() == ".elbowsim.lock";
    if (only_lock) {
      std::filesystem::remove(folder_ / ".elbowsim.lock", ignored);
      std::filesystem::remove(folder_, ignored);
    }
  }
  ::close(fd_);  // closing releases the lock
}

}  // namespace elbowsim

#include "app/output/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace elbowsim {

namespace {

// "<what> <path>: <the system's reason>" (errno as the failed call left it).
std::runtime_error io_error(const char* what, const std::filesystem::path& path, int error) {
  std::string text = std::string(what) + " " + path.string();
  if (error != 0) text += std::string(": ") + std::strerror(error);
  return std::runtime_error(text);
}

// Writes write(stream) to "<path>.tmp.<pid>" and returns that name; on any
// error nothing is left behind.
std::filesystem::path write_temporary(const std::filesystem::path& path,
                                      const std::function<void(std::ostream&)>& write) {
  // A name of this process's own: another process writing the same file
  // (without the folder lock, folder_lock.hpp) cannot write into ours.
  std::filesystem::path temporary = path;
  temporary += ".tmp." + std::to_string(::getpid());
  try {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw io_error("cannot write", temporary, errno);
    write(out);
    out.flush();
    if (!out) throw io_error("error while writing", temporary, errno);
    out.close();  // the last buffer reaches the disk here: check it too
    if (!out) throw io_error("error while writing", temporary, errno);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);  // nothing half-written left behind
    throw;
  }
  return temporary;
}

}  // namespace

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  std::filesystem::rename(write_temporary(path, write), path);
}

FileBatch::~FileBatch() { discard(); }

void FileBatch::add(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  try {
    entries_.push_back({path, write_temporary(path, write)});
  } catch (...) {
    discard();
    throw;
  }
}

void FileBatch::remove_at_commit(const std::filesystem::path& path) { entries_.push_back({path, {}}); }

void FileBatch::commit() {
  for (Entry& e : entries_) {
    if (e.temporary.empty())
      std::filesystem::remove_all(e.path);  // a file, or a folder (frames/, plots/)
    else
      std::filesystem::rename(e.temporary, e.path);
    e.temporary.clear();
  }
  entries_.clear();
}

void FileBatch::discard() noexcept {
  for (const Entry& e : entries_) {
    std::error_code ignored;
    if (!e.temporary.empty()) std::filesystem::remove(e.temporary, ignored);
  }
  entries_.clear();
}

}  // namespace elbowsim

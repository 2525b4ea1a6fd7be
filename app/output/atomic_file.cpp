#include "app/output/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <string>
#include <stdexcept>

namespace elbowsim {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  // A name of this process's own: another process writing the same file
  // (without the folder lock, folder_lock.hpp) cannot write into ours.
  std::filesystem::path temporary = path;
  temporary += ".tmp." + std::to_string(::getpid());
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
    write(out);
    out.flush();
    if (!out) throw std::runtime_error("error while writing " + temporary.string());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);  // nothing half-written left behind
    throw;
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace elbowsim

#include "app/output/atomic_file.hpp"

#include <fstream>
#include <stdexcept>

namespace elbowsim {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
    write(out);
    out.flush();
    if (!out) {
      std::filesystem::remove(temporary);
      throw std::runtime_error("error while writing " + temporary.string());
    }
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace elbowsim

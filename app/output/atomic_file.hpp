// Files written under a temporary name and renamed into place, so an
// interrupted run never leaves a half-written file behind.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace elbowsim {

// Calls write(stream) on "<path>.tmp.<pid>", then renames it to path; on any
// error (also one thrown by write) the temporary is removed. Throws
// std::runtime_error naming the path if the file cannot be written.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

}  // namespace elbowsim

// A fresh folder for a test's files, shared by every test suite. ctest sets TMPDIR to
// <build>/tests/scratch (tests/CMakeLists.txt), so two builds never share one.
#pragma once

#include <filesystem>
#include <string>

namespace elbowsim::testing {

// <temp>/elbowsim_<suite>_<name>, emptied (removed and created again) first, so a test
// never sees what an earlier run left there. `suite` keeps the suites apart
// ("cli", "render", "report", "variants").
inline std::filesystem::path scratch(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("elbowsim_" + suite + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace elbowsim::testing

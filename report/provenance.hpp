// Which program wrote an output: elbowsim's version, the git commit it was
// built from, its build type and compiler, fixed when it was built (CMake
// writes them into build_info.hpp: CMakeLists.txt, cmake/build_info.cmake).
// Every JSON file a command writes carries provenance_json() as its first key,
// "provenance"; every report's footer, provenance_line().
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace elbowsim::report {

struct Provenance {
  const char* version;     // the project's version (CMakeLists.txt)
  const char* commit;      // 12 hex digits, "-dirty" with uncommitted changes; or "unknown"
  const char* build_type;  // CMAKE_BUILD_TYPE: Release, Sanitize, ...
  const char* compiler;    // CMAKE_CXX_COMPILER_ID and version: "GNU 12.2.0"
};

// This program's (no allocation, no static initialisation: --version stays fast).
const Provenance& provenance();

// {"program": "elbowsim", "version", "commit", "build_type", "compiler"}.
nlohmann::ordered_json provenance_json();

// "elbowsim 0.1.0 (commit 0ae1fb498ed1, Release build, GNU 12.2.0)".
std::string provenance_line();

}  // namespace elbowsim::report

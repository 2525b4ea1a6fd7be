#include "report/provenance.hpp"

// Generated in the build tree (cmake/build_info.cmake); the only file that
// includes it, so that a new commit recompiles this file alone.
#include "build_info.hpp"

namespace elbowsim::report {

const Provenance& provenance() {
  static constexpr Provenance kThis{ELBOWSIM_VERSION, ELBOWSIM_COMMIT, ELBOWSIM_BUILD_TYPE,
                                    ELBOWSIM_COMPILER};
  return kThis;
}

nlohmann::ordered_json provenance_json() {
  const Provenance& p = provenance();
  return {{"program", "elbowsim"},
          {"version", p.version},
          {"commit", p.commit},
          {"build_type", p.build_type},
          {"compiler", p.compiler}};
}

std::string provenance_line() {
  const Provenance& p = provenance();
  return std::string("elbowsim ") + p.version + " (commit " + p.commit + ", " + p.build_type +
         " build, " + p.compiler + ")";
}

}  // namespace elbowsim::report

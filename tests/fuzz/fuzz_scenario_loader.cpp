// libFuzzer target: any bytes, as the text of a scenario file, through the loader
// (load_scenario_text: parse, overrides, every section reader, finalize, each
// variant; then the first case of a study, if it has one). A bad file must end in
// a ScenarioError, the loader's documented error; anything else that escapes
// (another exception, a crash, a sanitizer report, a hang) is a finding.
// Built with -DELBOWSIM_FUZZ=ON (clang); tests/fuzz/run.sh runs it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"

// As if the text were a file in scenarios/arms/: the shipped arms' robot.urdf
// paths resolve there, so the URDF import is fuzzed from their seeds too.
const std::string kFile = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/arms/fuzz.yaml";

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const elbowsim::Scenario scenario = elbowsim::load_scenario_text(text, kFile);
    if (!scenario.study.empty()) {
      std::vector<std::string> levels;
      for (const elbowsim::Scenario::StudyAxis& axis : scenario.study)
        levels.push_back(axis.levels.empty() ? std::string() : axis.levels.front().first);
      const std::string variant =
          scenario.variants.empty() ? std::string() : scenario.variants.front().first;
      elbowsim::load_scenario_case_text(text, kFile, levels, variant);
    }
  } catch (const elbowsim::ScenarioError&) {
    // A clean error: what bad input should get.
  }
  return 0;
}

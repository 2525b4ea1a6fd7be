// A scenario's text as key paths and values, to tell runs apart: which keys
// differ between the scenario.yaml files of several run folders (elbowsim
// compare shows them above its tables).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace elbowsim {

// Every leaf of the YAML text as (key path, value as one line of YAML), in
// file order: maps by key ("task.duration"), lists of maps by index
// ("robot.planar.links[1].mass"), a list of scalars as one value
// ("initial.q": "[0.1, 0.2]"). Text that does not parse gives nothing.
std::vector<std::pair<std::string, std::string>> scenario_keys(const std::string& yaml_text);

// The key paths whose values are not the same in every text (missing in
// one counts as different), each with its value per text ("" where missing),
// in order of first appearance.
struct KeyDifference {
  std::string key;
  std::vector<std::string> values;  // [texts]
};
std::vector<KeyDifference> differing_keys(const std::vector<std::string>& yaml_texts);

}  // namespace elbowsim

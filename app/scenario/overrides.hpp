// Command-line overrides: "key.path=yaml value" replaces (or adds) one value of
// a parsed scenario before it is read, e.g. "simulation.step=1e-4",
// "effects.motor=none", "robot.planar.links[0].mass=2", "inputs=" (removes).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "app/scenario/yaml_reader.hpp"

namespace elbowsim::loader {

// One step of a key path: a map key, a list index ("links[2]" is two steps),
// or every item of a list ("[*]", where a caller allows it).
constexpr long kMapKey = -1, kEveryItem = -2;
struct KeyStep {
  std::string key;        // a map key (index kMapKey), else empty
  long index = kMapKey;   // >= 0 for a list index; kEveryItem for [*]
};

// Splits "a.b[2].c" into its steps (appended to `out`); keys are letters,
// digits, _ and -. Returns "" or what is wrong: bad key "x" / bad index in
// "links[x]". `every_item` allows "[*]".
std::string parse_key_path(const std::string& path, bool every_item, std::vector<KeyStep>& out);

// Sets the value named by `text` in `root` (a map), creating missing maps on
// the way; list indices must exist. Records the override in `source` so that
// later errors in the value it set name it. Throws ScenarioError.
void apply_override(YAML::Node& root, const std::string& text, Source& source);
// Same, for an override given elsewhere (a variant's entry in the file):
// errors in the value it set are reported at `origin`.
void apply_override(YAML::Node& root, const std::string& text, Source& source,
                    const Source::Origin& origin);

}  // namespace elbowsim::loader

// Command-line overrides: "key.path=yaml value" replaces (or adds) one value of
// a parsed scenario before it is read, e.g. "simulation.step=1e-4",
// "effects.motor=none", "robot.planar.links[0].mass=2", "inputs=" (removes).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "app/scenario/yaml_reader.hpp"

namespace elbowsim::loader {

// Sets the value named by `text` in `root` (a map), creating missing maps on
// the way; list indices must exist. Records the override in `source` so that
// later errors in the value it set name it. Throws ScenarioError.
void apply_override(YAML::Node& root, const std::string& text, Source& source);
// Same, for an override given elsewhere (a variant's entry in the file):
// errors in the value it set are reported at `origin`.
void apply_override(YAML::Node& root, const std::string& text, Source& source,
                    const Source::Origin& origin);

}  // namespace elbowsim::loader

// A study file (elbowsim study): a scenario and the cases to run it at — a
// grid over scenario keys (every combination), or a list of cases, each
// optionally repeated over seeded draws of the scenario's uncertainty:
// section (a Monte Carlo design). scenarios/README.md, "Study files".
//
//   scenario: ../elbow_experiment.yaml   # relative to this file
//   set: [output.every=10]                # every case, before its own keys
//   grid:                                 # every combination, first key slowest
//     task.duration: [8, 4, 2]            # a key and its values
//     elbow:                              # or an axis of named levels
//       near: {initial.q: [0.76, -1.64, 1.54, -1.79]}
//       mid: {}
//   draws: 10                             # optional: each point drawn 10 times
//   seed: 1                               # default: uncertainty.seed
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim {

struct StudyDesign {
  // One level of an axis: what it is called in folder names and tables, and
  // the overrides it applies ("key.path=yaml value").
  struct Level {
    std::string label;
    std::vector<std::string> overrides;
  };
  // An axis of the grid: the values of one key (`key` set, one override per
  // level), or named levels of overrides (`key` empty).
  struct Axis {
    std::string name;  // the key path, or the axis' name
    std::string key;   // "" for named levels
    std::vector<Level> levels;
  };
  std::string file;                 // the study file; "" when given on the command line
  std::string name;                 // the study's name (file stem, or "study")
  std::string scenario;             // the scenario file, as a path from the working folder
  std::vector<std::string> sets;    // the study's own overrides, for every case
  std::vector<Axis> grid;           // every combination (first axis slowest)
  std::vector<std::vector<std::pair<std::string, std::string>>> list;  // cases: key -> yaml value
  long draws = 0;                   // 0: no Monte Carlo; else draws 0 .. draws-1 per point
  std::optional<std::uint64_t> seed;
};

// Whether `path` is a study file (a YAML map with a top-level `scenario:`);
// false for a scenario file or one that does not parse.
bool is_study_file(const std::string& path);

// Reads a study file. Throws ScenarioError naming file, line, column and key.
StudyDesign load_study_file(const std::string& path);

// An axis from the command line: "KEY=V1,V2,..." (commas inside [] or {} do
// not split). Throws ScenarioError naming the option.
StudyDesign::Axis grid_option(const std::string& text);

}  // namespace elbowsim

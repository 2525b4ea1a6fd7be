// A recorded run as the report sees it: the contents of one run folder
// (summary.json, trajectory.csv, events.csv, scenario.yaml, video.mp4 when
// the folder's manifest.json says this run made it), read
// by the command line (app/output/run_folder) and handed over as plain data.
// The report never simulates and never reaches into the engine.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "engine/recording/recording.hpp"

namespace elbowsim::report {

// One row of events.csv.
struct EventRow {
  double t = 0;            // [s]
  std::string elbow;       // elbow name
  std::string kind;        // "landing" or "release"
  double speed = 0;        // [m/s] normal speed at touchdown
  double impulse = 0;      // [N s]
  double energy_lost = 0;  // [J]
};

struct RunData {
  std::filesystem::path folder;
  std::string label;               // the folder's name: names the run in comparisons and --expect
  nlohmann::ordered_json summary;  // summary.json; null when the folder has none
  Recording trajectory;            // trajectory.csv; no columns when the folder has none
  std::vector<EventRow> events;    // events.csv (contact scenes)
  std::string scenario_yaml;       // scenario.yaml, the scenario as run; empty if absent
  // The model described from scenario.yaml ("links", "2: 0.4 m 1.3 kg, ..."),
  // empty when it could not be rebuilt.
  std::vector<std::pair<std::string, std::string>> model_rows;
  std::vector<std::string> problems;  // files missing or unreadable: shown in the report
  bool has_video = false;             // video.mp4 is there, made by the run (its manifest lists it)
  std::vector<std::string> files;     // the run's data files and video present in the folder

  bool has_summary() const { return summary.is_object(); }
  bool has_trajectory() const { return trajectory.rows() > 0; }
};

}  // namespace elbowsim::report

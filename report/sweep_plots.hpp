// Plots of a parameter sweep (elbowsim sweep): hand error and energy against
// the swept value, one line per variant — the task-speed study (key
// task.duration) and the elbow-position study (key elbows[0].at).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace elbowsim::report {

struct SweepPoint {
  double value;                    // the swept key's value
  std::string variant;             // "" without variants
  nlohmann::ordered_json summary;  // the run's summary.json
};

// Writes sweep_hand_error.png (RMS and max, log axis; only when the runs have
// a task) and sweep_energy.png (electrical energy in and Joule loss) into
// `folder`. Returns the files written.
std::vector<std::filesystem::path> write_sweep_plots(const std::string& key,
                                                     const std::vector<SweepPoint>& points,
                                                     const std::filesystem::path& folder);

}  // namespace elbowsim::report

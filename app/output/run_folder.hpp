// Reading a run folder back (what `elbowsim run` wrote) for reports and
// comparisons: summary.json, trajectory.csv, events.csv, scenario.yaml and
// whether video.mp4 is there.
#pragma once

#include <filesystem>
#include <stdexcept>

#include "report/run_data.hpp"

namespace elbowsim {

// The folder is missing or holds neither summary.json nor trajectory.csv.
class NotARunFolder : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads what the folder holds. A missing or unreadable file is noted in
// RunData::problems rather than thrown, so that a report can still be made
// from what is there (a failed run's partial outputs, say); the label is the
// folder's name. Throws NotARunFolder when there is nothing to report on.
report::RunData load_run_folder(const std::filesystem::path& folder);

}  // namespace elbowsim

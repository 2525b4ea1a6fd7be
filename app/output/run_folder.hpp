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

// The folder's files were cut or do not belong together.
class InconsistentRunFolder : public NotARunFolder {
 public:
  using NotARunFolder::NotARunFolder;
};

// Reads what the folder holds. A missing file (or a scenario.yaml whose model
// cannot be rebuilt) is noted in RunData::problems rather than thrown, so
// that a report can still be made from what is there; the label is the
// folder's name. Throws NotARunFolder when there is nothing to report on, and
// InconsistentRunFolder when a file is there but cut or damaged, or
// trajectory.csv and summary.json disagree on where the run ended
// (inconsistency()).
report::RunData load_run_folder(const std::filesystem::path& folder);

// Why a loaded folder cannot be trusted ("" when it can): summary.json,
// trajectory.csv or events.csv unreadable, or the trajectory's last time
// after the summary's final_time (or, for a completed run, before it).
std::string inconsistency(const report::RunData& run);

}  // namespace elbowsim

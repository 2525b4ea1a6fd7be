// manifest.json: what the last run into a folder wrote. A run folder is
// rewritten in place (other results may sit beside it: montecarlo/, sweep/),
// so it is kept whole another way: the run commits its data files together
// with a new manifest and, in the same commit, removes every artefact an
// earlier run left that derives from the old data (video.mp4, frames/,
// report.html, plots/, and data files this run does not write). What comes
// after (the video, the report) is added to the manifest when it is written.
// A report embeds only what the manifest lists, so it never shows a stale
// video as this run's.
//
//   {"written_by": "elbowsim run", "files": ["scenario.yaml", "trajectory.csv",
//    "summary.json", "video.mp4", "report.html", "plots/"]}
//
// A folder written before manifests existed has none: its files are taken as
// they are (read_manifest returns nullopt).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim {

inline constexpr const char* kManifestFile = "manifest.json";

// Files a run derives from its data after writing it; removed when new data
// is committed, so that none outlives the data it was made from.
const std::vector<std::string>& derived_artefacts();  // video.mp4, frames, report.html, plots

// The manifest's text for these entries (relative paths, "plots/" for a folder).
std::string manifest_text(const std::vector<std::string>& files);

// The entries of <folder>/manifest.json; nullopt when there is none. Throws
// std::runtime_error naming the file when it is there but unreadable.
std::optional<std::vector<std::string>> read_manifest(const std::filesystem::path& folder);

// Adds entries to an existing manifest (rewritten atomically); does nothing
// in a folder without one. Throws std::runtime_error naming the file on an
// I/O error.
void add_to_manifest(const std::filesystem::path& folder, const std::vector<std::string>& files);

// After rendering into a run folder: adds video.mp4 (when `video`) and
// frames/ (when `frames`) to its manifest where they now exist.
void record_rendered(const std::filesystem::path& folder, bool video, bool frames);

// Whether `file` ("video.mp4", "plots/a.png") belongs to the folder's run:
// listed (itself or its folder "plots/"), or any existing file when the
// folder has no manifest.
bool written_by_run(const std::optional<std::vector<std::string>>& manifest,
                    const std::filesystem::path& folder, const std::string& file);

}  // namespace elbowsim

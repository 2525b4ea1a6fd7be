// case.json: what one case of a study (elbowsim study) ended with, written
// last into the case's folder, after every run of it is committed. A case is
// finished when its case.json is there and every run it names is complete by
// its own manifest.json (every file listed is there); a case stopped midway
// (killed, interrupted) has none and is run again by the next `study`.
//
//   {"index": 3, "folder": "003-duration_2", "status": "done",
//    "runs": [{"variant": "elbow_on", "folder": "elbow_on"}, ...],
//    "failures": [{"variant": "elbow_off", "reason": "..."}]}
//
// status: "done" (every run valid) or "failed" (a run stopped early or is
// invalid, or the drawn values do not load; the reasons in "failures").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace elbowsim::study {

inline constexpr const char* kCaseFile = "case.json";

struct CaseRecord {
  long index = 0;
  std::string folder;
  std::string status;  // "done" or "failed"
  std::vector<std::string> variants;  // "" for a scenario without variants (its run is the case folder)
  std::vector<std::pair<std::string, std::string>> failures;  // variant, reason
};

// Writes <case_folder>/case.json atomically. Throws std::runtime_error on an I/O error.
void write_case_record(const std::filesystem::path& case_folder, const CaseRecord& record);

// The record of a finished case; nullopt when case.json is missing or
// unreadable, or a run it names lacks a file its manifest lists.
std::optional<CaseRecord> finished_case(const std::filesystem::path& case_folder);

// The folder of a case's run of `variant` ("" : the case folder itself).
std::filesystem::path run_folder(const std::filesystem::path& case_folder, const std::string& variant);

}  // namespace elbowsim::study

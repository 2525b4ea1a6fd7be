// The results of a study over its cases: study.json (per case its levels,
// each variant's mean drawn and net electrical energy and RMS hand error with
// their intervals, the paired statistics of study::kCompared with their
// outcomes, and the reason of each "no verdict"; a tally of outcomes per pair
// of variants and the verdict over the cases) and study.csv (one row per case
// and pair). A case whose statistic could not be computed keeps its row.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"
#include "app/study/cases.hpp"

namespace elbowsim::study {

// `case_docs[k]` is the montecarlo.json of `cases[k]`.
nlohmann::ordered_json study_document(const Scenario& base, const std::string& file,
                                      const std::vector<StudyCase>& cases,
                                      const std::vector<nlohmann::ordered_json>& case_docs);

void write_study_csv(const std::filesystem::path& path, const nlohmann::ordered_json& study);

}  // namespace elbowsim::study

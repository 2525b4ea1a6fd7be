// The work-precision study's outputs (elbowsim accuracy), from accuracy.json
// alone: the verdict, work_precision.csv, the log-log plots (error against
// CPU time, one line per method, one plot per error measure and variant) and
// report.html leading with the verdict.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace elbowsim::report {

// For each variant's study (doc["studies"][k], as app/study/work_precision
// makes it) and each target of the maximum hand error [m]: the valid point
// with the least CPU time that meets it, the cheapest point of another method
// that meets it, and their cost ratio. A target finer than the reference's
// uncertainty is not judged (nothing can be shown to meet it).
nlohmann::ordered_json work_precision_verdict(const nlohmann::ordered_json& doc,
                                              const std::vector<double>& targets = {1e-3, 1e-6, 1e-9});

// One row per point and alternative of every study; errors against the reference.
std::string work_precision_csv(const nlohmann::ordered_json& doc);

// Writes folder/plots/*.png and folder/report.html from doc (with its
// "verdict"). Throws std::runtime_error naming the file on failure.
void write_accuracy_report(const nlohmann::ordered_json& doc, const std::filesystem::path& folder);

}  // namespace elbowsim::report

// Comparing recorded runs: every metric side by side with its relative
// difference to the first run, and verdict sentences computed from the
// numbers ("elbow_on: 38 % less electrical energy than elbow_off"). Variants
// (elbow on/off, integrators, ...) and work-precision studies reuse this.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "report/run_data.hpp"

namespace elbowsim::report {

struct ComparedMetric {
  std::string path;  // "energy_final.electrical_in", "trajectory.rms_current.i0"
  std::string unit;
  std::vector<nlohmann::ordered_json> values;  // [runs]; null where a run lacks the metric
  // [runs] (value - reference) / |reference| with run 0 the reference; empty
  // where not a number on both sides or the reference is 0 (and the value not).
  std::vector<std::optional<double>> relative;
};

struct Comparison {
  std::vector<std::string> labels;      // [runs]
  std::vector<ComparedMetric> metrics;  // summary.json metrics, then trajectory.* ones
  std::vector<std::string> verdict;     // sentences, most important first
};

// Labels for runs from their folder names; a repeated name gets "_2", "_3", ...
std::vector<std::string> unique_labels(const std::vector<std::string>& folder_names);

Comparison compare_runs(const std::vector<RunData>& runs);

// The verdict alone (what compare_runs puts in Comparison::verdict).
std::vector<std::string> verdict(const std::vector<RunData>& runs, const Comparison& table);

// The comparison as JSON (comparison.json): labels, metrics with values and
// relative differences, verdict.
nlohmann::ordered_json comparison_json(const Comparison& comparison);

}  // namespace elbowsim::report

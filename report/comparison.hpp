// Comparing recorded runs: every number of their summaries side by side with
// its relative difference to the first run and whether it differs beyond its
// noise floor (noise_floor.hpp), and verdict sentences computed from the
// numbers ("elbow_on: 38 % less electrical energy drawn from the supply than
// elbow_off").
// The one writer of comparison.json and comparison.csv (`compare`, variants)
// and of sweep.csv (`sweep`).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "report/noise_floor.hpp"
#include "report/run_data.hpp"

namespace elbowsim::report {

struct ComparedMetric {
  std::string path;  // "energy_final.electrical_in", "trajectory.rms_current.i0"
  std::string unit;
  std::vector<nlohmann::ordered_json> values;  // [runs]; null where a run lacks the metric
  // [runs] (value - reference) / |reference| with run 0 the reference; empty
  // where not a number on both sides or the reference is 0 (and the value not).
  std::vector<std::optional<double>> relative;
  MetricKind kind = MetricKind::result;
  NoiseFloor floor;  // report/noise_floor.hpp
  bool same = true;  // every run within the floor of the first
};

struct Comparison {
  std::vector<std::string> labels;      // [runs]
  std::vector<std::string> folders;     // [runs] run folders, as given
  std::vector<bool> completed;          // [runs] summary.json "completed"
  std::vector<bool> valid;              // [runs] summary.json "valid" (engine/run/validity.hpp)
  std::vector<std::string> failures;    // [runs] summary.json "failure"
  std::vector<ComparedMetric> metrics;  // the numbers of summary.json (run_metrics), in order
  std::vector<std::string> verdict;     // sentences, most important first
  // The scenario keys whose values differ between the runs: key, value per run
  // ("" where a run does not set it). Filled by the caller (it reads YAML).
  std::vector<std::pair<std::string, std::vector<std::string>>> differing_keys;
};

// Labels for runs from their folder names; a repeated name gets "_2", "_3", ...
std::vector<std::string> unique_labels(const std::vector<std::string>& folder_names);

Comparison compare_runs(const std::vector<RunData>& runs);

// Whether a run's numbers can be compared: summary.json says valid (older
// summaries: completed).
bool is_valid(const RunData& run);

// The verdict alone (what compare_runs puts in Comparison::verdict): the runs
// that are not valid, and then no verdict; else the energy and accuracy sentences.
std::vector<std::string> verdict(const std::vector<RunData>& runs, const Comparison& table);

// comparison.json: runs (labels), reference (the first), folder, completed
// and failure per run, verdict, and metrics: a list of {path, unit, kind,
// values: {run: x}, relative: {run: (x - x_ref)/|x_ref|}, floor, floor_basis,
// same}, null where undefined.
nlohmann::ordered_json comparison_json(const Comparison& comparison);

// comparison.csv: one row per run: its label (under `first_header`),
// completed, each metric ("path [unit]"), then each metric's relative
// difference to the first run ("path rel"). Numbers as in summary.json (the
// shortest round trip); an undefined one is an empty cell.
void write_comparison_csv(std::ostream& out, const Comparison& comparison,
                          const std::string& first_header = "run");

// sweep.csv: one row per run of a sweep: the swept key's value, the run's
// variant ("" without variants), completed, then each metric ("path [unit]").
// values[k] and variants[k] belong to runs[k].
void write_sweep_csv(std::ostream& out, const std::string& key,
                     const std::vector<std::string>& values,
                     const std::vector<std::string>& variants, const std::vector<RunData>& runs);

}  // namespace elbowsim::report

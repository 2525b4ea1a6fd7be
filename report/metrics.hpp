// The numbers a report tabulates: every number and flag of summary.json under
// its dotted path (the same names --expect uses), and a few figures derived
// from the trajectory that summary.json does not hold.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/recording/recording.hpp"

namespace elbowsim::report {

struct Metric {
  std::string path;  // "energy_final.electrical_in"
  nlohmann::ordered_json
      value;         // a number or a boolean (null: a NaN that summary.json wrote as null)
  std::string unit;  // "J"; empty when dimensionless or unknown
};

// Every number, boolean and null leaf of summary.json in file order, list
// entries by index (metrics.current_peak.0), with units where the key says
// (energy_* -> J, ...). Strings are not metrics.
std::vector<Metric> summary_metrics(const nlohmann::ordered_json& summary);

// The unit of a summary.json metric path; "" when it has none.
std::string metric_unit(const std::string& path);

// Figures from trajectory.csv, under "trajectory.*": per motor the peak and
// RMS current, the electrical energy integrated from the samples (a cross-
// check of energy_final.electrical_in), the peak power; per elbow the peak
// normal force, the fraction of time at rest and the largest |d| while
// resting; the hand's path length; the RMS and peak hand error when recorded.
std::vector<Metric> trajectory_metrics(const Recording& rec);

// The value of `path` among `metrics`, or nullptr.
const Metric* find_metric(const std::vector<Metric>& metrics, const std::string& path);

}  // namespace elbowsim::report

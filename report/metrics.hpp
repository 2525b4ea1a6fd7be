// The numbers a report tabulates: every number and flag of summary.json under
// its dotted path (the same names --expect uses). The run's metrics under
// "metrics." are those of engine/recording/metrics.hpp (one vocabulary, with
// units); a run folder without them in summary.json gets them computed from
// its trajectory.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/recording/metrics.hpp"
#include "report/run_data.hpp"

namespace elbowsim::report {

struct Metric {
  std::string path;  // "energy_final.electrical_in"
  nlohmann::ordered_json
      value;         // a number or a boolean (null: a NaN that summary.json wrote as null)
  std::string unit;  // "J"; empty when dimensionless or unknown
};

// The run's metrics as summary.json writes them: one value as a number, per
// joint as a list, per elbow as an object keyed by elbow name (so --expect
// reads metrics.current_peak.0 and metrics.rest_fraction.elbow).
nlohmann::ordered_json metrics_json(const Metrics& metrics);

// Every number, boolean and null leaf of summary.json in file order, list
// entries by index (metrics.current_peak.0), with units where the key says
// (energy_* -> J, metrics.* from the metrics vocabulary, ...). Strings are not metrics.
std::vector<Metric> summary_metrics(const nlohmann::ordered_json& summary);

// summary_metrics of the run, plus "metrics.*" computed from its trajectory
// when summary.json has no "metrics" (an older or partial run folder).
std::vector<Metric> run_metrics(const RunData& run);

// The unit a report shows for a summary.json path (summary_units.hpp), "" for a pure
// number and for a path without one.
std::string metric_unit(const std::string& path);

// The value of `path` among `metrics`, or nullptr.
const Metric* find_metric(const std::vector<Metric>& metrics, const std::string& path);

}  // namespace elbowsim::report

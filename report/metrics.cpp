#include "report/metrics.hpp"

#include <algorithm>
#include <cmath>

#include "report/summary_keys.hpp"
#include "report/summary_units.hpp"

namespace elbowsim::report {

namespace {

void flatten(const nlohmann::ordered_json& node, const std::string& path,
             std::vector<Metric>& out) {
  if (node.is_object() || node.is_array()) {  // lists by index: metrics.current_peak.0
    for (const auto& [key, value] : node.items())
      flatten(value, path.empty() ? key : path + "." + key, out);
    return;
  }
  if (node.is_number() || node.is_boolean() || node.is_null())
    out.push_back({path, node, metric_unit(path)});
}

}  // namespace

std::string metric_unit(const std::string& path) {
  const std::string unit = summary_unit(path);  // the one table: summary_units.cpp
  return unit == "1" ? "" : unit;
}

std::vector<Metric> summary_metrics(const nlohmann::ordered_json& summary) {
  std::vector<Metric> out;
  if (summary.is_object()) flatten(summary, "", out);
  return out;
}

nlohmann::ordered_json metrics_json(const Metrics& metrics) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const elbowsim::Metric& m : metrics.list) {
    switch (m.shape) {
      case elbowsim::Metric::Shape::one: j[m.name] = m.values[0]; break;
      case elbowsim::Metric::Shape::per_joint: j[m.name] = m.values; break;
      case elbowsim::Metric::Shape::per_elbow:
        j[m.name] = nlohmann::ordered_json::object();
        for (std::size_t k = 0; k < m.values.size(); ++k) j[m.name][metrics.elbows[k]] = m.values[k];
        break;
      case elbowsim::Metric::Shape::per_body:  // summary.json's contact.bodies holds these
        break;
    }
  }
  return j;
}

std::vector<Metric> run_metrics(const RunData& run) {
  std::vector<Metric> out = summary_metrics(run.summary);
  const SummaryKey& metrics = summary_key::metrics;
  const bool recorded = run.has_summary() && run.summary.contains(metrics.name());
  if (!recorded && run.has_trajectory())
    flatten(metrics_json(compute_metrics(run.trajectory)), std::string(metrics.path), out);
  return out;
}

const Metric* find_metric(const std::vector<Metric>& metrics, const std::string& path) {
  for (const Metric& m : metrics)
    if (m.path == path) return &m;
  return nullptr;
}

}  // namespace elbowsim::report

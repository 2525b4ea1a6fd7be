#include "report/metrics.hpp"

#include <algorithm>
#include <cmath>

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

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

std::string metric_unit(const std::string& path) {
  if (starts_with(path, "energy_initial.") || starts_with(path, "energy_final.")) return "J";
  if (path == "balance_residual" || path == "max_abs_balance_residual") return "J";
  if (path == "final_time" || path == "wall_seconds" || path == "settings.step" ||
      path == "settings.duration")
    return "s";
  if (path == "model.total_mass") return "kg";
  if (path == "contact.max_abs_C") return "m";
  if (path == "contact.max_abs_Jc_qd") return "m/s";
  if (starts_with(path, "contact.bodies.")) {  // contact.bodies.<body>.<quantity>
    const std::string quantity = path.substr(path.rfind('.') + 1);
    if (quantity == "force_mean" || quantity == "force_peak") return "N";
    if (quantity == "friction_work") return "J";
    return "";
  }
  if (starts_with(path, "metrics.")) {  // metrics.<name>[.<joint or elbow>]
    const std::string rest = path.substr(8);
    return elbowsim::metric_unit(rest.substr(0, rest.find('.')));
  }
  return "";
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
  const bool recorded = run.has_summary() && run.summary.contains("metrics");
  if (!recorded && run.has_trajectory())
    flatten(metrics_json(compute_metrics(run.trajectory)), "metrics", out);
  return out;
}

const Metric* find_metric(const std::vector<Metric>& metrics, const std::string& path) {
  for (const Metric& m : metrics)
    if (m.path == path) return &m;
  return nullptr;
}

}  // namespace elbowsim::report

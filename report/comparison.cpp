#include "report/comparison.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "report/metrics.hpp"

namespace elbowsim::report {

namespace {

// The union of the runs' metric paths, in first-seen order.
std::vector<Metric> union_of(const std::vector<std::vector<Metric>>& per_run) {
  std::vector<Metric> paths;
  for (const auto& metrics : per_run)
    for (const Metric& m : metrics)
      if (!find_metric(paths, m.path)) paths.push_back(m);
  return paths;
}

std::optional<double> relative_difference(const nlohmann::ordered_json& value,
                                          const nlohmann::ordered_json& reference) {
  if (!value.is_number() || !reference.is_number()) return std::nullopt;
  const double v = value.get<double>(), ref = reference.get<double>();
  if (ref == 0) return v == 0 ? std::optional<double>(0.0) : std::nullopt;
  return (v - ref) / std::abs(ref);
}

void add_rows(const std::vector<std::vector<Metric>>& per_run, std::vector<ComparedMetric>& out) {
  for (const Metric& m : union_of(per_run)) {
    ComparedMetric row{m.path, m.unit, {}, {}};
    for (const auto& metrics : per_run) {
      const Metric* found = find_metric(metrics, m.path);
      row.values.push_back(found ? found->value : nlohmann::ordered_json());
    }
    for (const auto& value : row.values)
      row.relative.push_back(relative_difference(value, row.values[0]));
    out.push_back(std::move(row));
  }
}

std::string quantity(double v, const std::string& unit) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3g", v);
  return unit.empty() ? text : std::string(text) + " " + unit;
}

std::string percent(double p) {
  char text[32];
  std::snprintf(text, sizeof text, p >= 9.95 ? "%.0f %%" : "%.1f %%", p);
  return text;
}

// "<best>: 38 % less <what> than <other> (4.1 J vs 6.6 J)" for each other
// run, where smaller is better; or why the metric is not compared.
std::vector<std::string> smaller_is_better(const Comparison& table, const std::string& path,
                                           const std::string& less, const std::string& what) {
  const ComparedMetric* row = nullptr;
  for (const ComparedMetric& m : table.metrics)
    if (m.path == path) row = &m;
  std::vector<std::string> missing;
  for (std::size_t r = 0; r < table.labels.size(); ++r)
    if (!row || !row->values[r].is_number()) missing.push_back(table.labels[r]);
  if (!missing.empty()) {
    std::string who;
    for (const auto& m : missing) who += (who.empty() ? "" : ", ") + m;
    return {"The " + what + " is not compared: " + who + " lack" +
            (missing.size() == 1 ? "s " : " ") + path + "."};
  }
  std::size_t best = 0;
  for (std::size_t r = 1; r < row->values.size(); ++r)
    if (row->values[r].get<double>() < row->values[best].get<double>()) best = r;
  const double b = row->values[best].get<double>();
  std::vector<std::string> sentences;
  for (std::size_t r = 0; r < row->values.size(); ++r) {
    if (r == best) continue;
    const double o = row->values[r].get<double>();
    const std::string both = " (" + quantity(b, row->unit) + " vs " + quantity(o, row->unit) + ")";
    const std::string& lb = table.labels[best];
    const std::string& lo = table.labels[r];
    const double p = o != 0 ? 100 * (o - b) / std::abs(o) : 0;
    if (o == b || (o != 0 && p < 0.5))
      sentences.push_back(lb + " and " + lo + ": the same " + what + " within 0.5 %" + both + ".");
    else if (o == 0 || o < 0)
      sentences.push_back(lb + ": " + less + " " + what + " than " + lo + both + ".");
    else
      sentences.push_back(lb + ": " + percent(p) + " " + less + " " + what + " than " + lo + both +
                          ".");
  }
  return sentences;
}

std::vector<std::string> failures(const std::vector<RunData>& runs) {
  std::vector<std::string> sentences;
  for (const RunData& run : runs) {
    if (!run.has_summary()) {
      sentences.push_back(run.label + " has no summary.json: its numbers are missing.");
      continue;
    }
    if (run.summary.value("completed", true)) continue;
    sentences.push_back(run.label + " did not complete (" + run.summary.value("failure", "") +
                        "): its totals cover t = 0 to " +
                        quantity(run.summary.value("final_time", 0.0), "s") + " only.");
  }
  return sentences;
}

bool all_zero(const Comparison& table, const std::string& path) {
  for (const ComparedMetric& m : table.metrics)
    if (m.path == path) {
      for (const auto& v : m.values)
        if (!v.is_number() || v.get<double>() != 0) return false;
      return true;
    }
  return false;
}

}  // namespace

std::vector<std::string> unique_labels(const std::vector<std::string>& folder_names) {
  std::vector<std::string> labels;
  std::map<std::string, int> seen;
  for (const std::string& name : folder_names) {
    const int n = ++seen[name];
    labels.push_back(n == 1 ? name : name + "_" + std::to_string(n));
  }
  return labels;
}

std::vector<std::string> verdict(const std::vector<RunData>& runs, const Comparison& table) {
  std::vector<std::string> sentences = failures(runs);
  if (all_zero(table, "energy_final.electrical_in"))
    sentences.push_back("No run drew electrical energy (energy_final.electrical_in is 0 in all).");
  else
    for (auto& s :
         smaller_is_better(table, "energy_final.electrical_in", "less", "electrical energy"))
      sentences.push_back(std::move(s));
  // Accuracy: the engine's RMS hand error (summary.json metrics) when the runs
  // have it, else the one computed from the recorded hand_error column.
  const char* accuracy = nullptr;
  for (const char* path : {"trajectory.rms_hand_error", "metrics.hand_error_rms"})
    for (const ComparedMetric& m : table.metrics)
      if (m.path == path) accuracy = path;
  if (!accuracy)
    sentences.push_back("Hand accuracy is not compared: no run recorded a hand_error column.");
  else
    for (auto& s : smaller_is_better(table, accuracy, "smaller", "RMS hand error"))
      sentences.push_back(std::move(s));
  return sentences;
}

Comparison compare_runs(const std::vector<RunData>& runs) {
  Comparison c;
  std::vector<std::vector<Metric>> from_summary, from_trajectory;
  for (const RunData& run : runs) {
    c.labels.push_back(run.label);
    from_summary.push_back(summary_metrics(run.summary));
    from_trajectory.push_back(trajectory_metrics(run.trajectory));
  }
  add_rows(from_summary, c.metrics);
  add_rows(from_trajectory, c.metrics);
  c.verdict = verdict(runs, c);
  return c;
}

nlohmann::ordered_json comparison_json(const Comparison& comparison) {
  nlohmann::ordered_json j;
  j["runs"] = comparison.labels;
  j["reference"] = comparison.labels.empty() ? "" : comparison.labels[0];
  j["verdict"] = comparison.verdict;
  j["metrics"] = nlohmann::ordered_json::array();
  for (const ComparedMetric& m : comparison.metrics) {
    nlohmann::ordered_json row = {{"path", m.path}, {"unit", m.unit}};
    for (std::size_t r = 0; r < comparison.labels.size(); ++r) {
      row["values"][comparison.labels[r]] = m.values[r];
      row["relative"][comparison.labels[r]] =
          m.relative[r] ? nlohmann::ordered_json(*m.relative[r]) : nlohmann::ordered_json();
    }
    j["metrics"].push_back(std::move(row));
  }
  return j;
}

}  // namespace elbowsim::report

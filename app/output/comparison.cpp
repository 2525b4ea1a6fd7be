#include "app/output/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace elbowsim {

namespace {

using Json = nlohmann::ordered_json;
using Metrics = std::vector<std::pair<std::string, double>>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Numbers, arrays and objects below `prefix`, depth first, in order.
void flatten(const Json& j, const std::string& prefix, Metrics& out) {
  if (j.is_number()) {
    out.emplace_back(prefix, j.get<double>());
  } else if (j.is_null()) {
    out.emplace_back(prefix, kNaN);  // NaN is written to JSON as null
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      flatten(j[i], prefix + "[" + std::to_string(i) + "]", out);
  } else if (j.is_object()) {
    for (const auto& [key, value] : j.items())
      flatten(value, prefix.empty() ? key : prefix + "." + key, out);
  }
}

double number_at(const Json& summary, const Json::json_pointer& pointer) {
  return summary.contains(pointer) && summary[pointer].is_number() ? summary[pointer].get<double>()
                                                                   : kNaN;
}

bool completed(const Json& summary) { return summary.value("completed", false); }

// Metric names in first-seen order over all runs, and each run's values by
// name (NaN where a run lacks one).
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;  // [run][metric]
};

Table make_table(const std::vector<const Json*>& summaries) {
  Table t;
  std::vector<Metrics> per_run;
  for (const Json* s : summaries) {
    // A run that stopped before its first step (its task could not be
    // planned) has no metrics, only zeros in its summary.
    const bool ran = completed(*s) || s->value("steps", 0L) > 0;
    per_run.push_back(ran ? summary_metrics(*s) : Metrics());
    for (const auto& [name, value] : per_run.back())
      if (std::find(t.names.begin(), t.names.end(), name) == t.names.end()) t.names.push_back(name);
  }
  for (const Metrics& m : per_run) {
    std::vector<double> row(t.names.size(), kNaN);
    for (const auto& [name, value] : m)
      row[std::find(t.names.begin(), t.names.end(), name) - t.names.begin()] = value;
    t.values.push_back(std::move(row));
  }
  return t;
}

// A number as summary.json writes it (shortest round trip); "" for NaN/inf.
std::string cell(double x) { return std::isfinite(x) ? Json(x).dump() : ""; }

// A CSV field, quoted when it holds a comma, quote or line break.
std::string field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string header(const std::string& name) {
  const std::string unit = metric_unit(name);
  return field(unit.empty() ? name : name + " [" + unit + "]");
}

Json number_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

}  // namespace

Metrics summary_metrics(const Json& summary) {
  Metrics out;
  if (summary.contains("metrics") && summary["metrics"].is_object()) {
    flatten(summary["metrics"], "", out);
    return out;
  }
  for (const char* path :
       {"/energy_final/electrical_in", "/energy_final/joule", "/balance_residual"}) {
    std::string name = std::string(path + 1);
    std::replace(name.begin(), name.end(), '/', '.');
    out.emplace_back(name, number_at(summary, Json::json_pointer(path)));
  }
  return out;
}

std::string metric_unit(const std::string& name) {
  const std::string base = name.substr(0, name.find('['));
  auto starts = [&](const char* prefix) { return base.rfind(prefix, 0) == 0; };
  if (starts("hand_error")) return "m";
  if (starts("energy") || starts("joule") || starts("balance_residual")) return "J";
  if (starts("current")) return "A";
  if (starts("elbow_force")) return "N";
  if (starts("time_in_contact")) return "s";
  return "";
}

double relative_difference(double x, double reference) {
  if (x == reference) return 0.0;  // also both 0
  return reference != 0 ? (x - reference) / std::abs(reference) : kNaN;
}

Json comparison_json(const std::string& scenario, const std::vector<RunRecord>& runs) {
  std::vector<const Json*> summaries;
  for (const RunRecord& r : runs) summaries.push_back(&r.summary);
  const Table t = make_table(summaries);
  Json j;
  j["scenario"] = scenario;
  j["runs"] = Json::array();
  for (const RunRecord& r : runs) j["runs"].push_back(r.variant);
  j["reference"] = runs.empty() ? "" : runs.front().variant;
  for (const char* key : {"folder", "completed", "failure"}) j[key] = Json::object();
  for (const RunRecord& r : runs) {
    j["folder"][r.variant] = r.folder;
    j["completed"][r.variant] = completed(r.summary);
    j["failure"][r.variant] = r.summary.value("failure", "");
  }
  j["metrics"] = Json::array();
  for (std::size_t m = 0; m < t.names.size(); ++m) {
    Json row = {{"path", t.names[m]}, {"unit", metric_unit(t.names[m])}};
    for (std::size_t r = 0; r < runs.size(); ++r) {
      row["values"][runs[r].variant] = number_or_null(t.values[r][m]);
      row["relative"][runs[r].variant] =
          number_or_null(relative_difference(t.values[r][m], t.values[0][m]));
    }
    j["metrics"].push_back(std::move(row));
  }
  return j;
}

void write_comparison_csv(std::ostream& out, const std::vector<RunRecord>& runs) {
  std::vector<const Json*> summaries;
  for (const RunRecord& r : runs) summaries.push_back(&r.summary);
  const Table t = make_table(summaries);
  out << "variant,completed";
  for (const std::string& name : t.names) out << ',' << header(name);
  for (const std::string& name : t.names) out << ',' << field(name + " rel");
  out << '\n';
  for (std::size_t r = 0; r < runs.size(); ++r) {
    out << field(runs[r].variant) << ',' << (completed(runs[r].summary) ? "true" : "false");
    for (double x : t.values[r]) out << ',' << cell(x);
    for (std::size_t m = 0; m < t.names.size(); ++m)
      out << ',' << cell(relative_difference(t.values[r][m], t.values[0][m]));
    out << '\n';
  }
}

void write_sweep_csv(std::ostream& out, const std::string& key, const std::vector<SweepRow>& rows) {
  std::vector<const Json*> summaries;
  for (const SweepRow& row : rows) summaries.push_back(&row.run.summary);
  const Table t = make_table(summaries);
  out << field(key) << ",variant,completed";
  for (const std::string& name : t.names) out << ',' << header(name);
  out << '\n';
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out << field(rows[r].value) << ',' << field(rows[r].run.variant) << ','
        << (completed(rows[r].run.summary) ? "true" : "false");
    for (double x : t.values[r]) out << ',' << cell(x);
    out << '\n';
  }
}

}  // namespace elbowsim

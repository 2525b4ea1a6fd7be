#include "report/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "engine/recording/number_text.hpp"
#include "report/headline.hpp"
#include "report/metrics.hpp"
#include "report/provenance.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

namespace key = summary_key;

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

// Numbers only: flags (completed, contact.enabled, ...) are not metrics to compare.
void add_rows(const std::vector<RunData>& runs, const std::vector<std::vector<Metric>>& per_run,
              std::vector<ComparedMetric>& out) {
  for (const Metric& m : union_of(per_run)) {
    if (m.value.is_boolean()) continue;
    ComparedMetric row{m.path, m.unit, {}, {}, metric_kind(m.path), {}, true};
    for (const auto& metrics : per_run) {
      const Metric* found = find_metric(metrics, m.path);
      row.values.push_back(found ? found->value : nlohmann::ordered_json());
    }
    for (const auto& value : row.values)
      row.relative.push_back(relative_difference(value, row.values[0]));
    row.floor = noise_floor(m.path, runs, per_run);
    row.same = same_within(row.values, row.kind, row.floor, m.path);
    out.push_back(std::move(row));
  }
}

// "<best>: 38 % less <what> than <other> (4.1 J vs 6.6 J)" for each other
// run, where smaller is better; or why the metric is not compared. A
// percentage only of values >= 0 (a share of the larger one, at most 100 %);
// where a value is negative (a net energy the motors fed back) the
// difference in its unit: "<best>: 1.2 J less <what> than <other>".
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
    // Enough digits to tell the two apart (10.0 J vs 10.003 J, not 10 J vs 10 J).
    int digits = 3;
    while (digits < 9 && b != o && quantity(b, row->unit, digits) == quantity(o, row->unit, digits))
      ++digits;
    const std::string both =
        " (" + quantity(b, row->unit, digits) + " vs " + quantity(o, row->unit, digits) + ")";
    const std::string& lb = table.labels[best];
    const std::string& lo = table.labels[r];
    const double p = o != 0 ? 100 * (o - b) / std::abs(o) : 0;
    if (std::abs(o - b) <= row->floor.value)
      sentences.push_back(lb + " and " + lo + ": the same " + what + " within its noise floor (" +
                          quantity(row->floor.value, row->unit) + ", " + row->floor.basis + ")" +
                          both + ".");
    else if (!(b >= 0 && o > 0))
      sentences.push_back(lb + ": " + quantity(o - b, row->unit) + " " + less + " " + what +
                          " than " + lo + both + ".");
    else
      // Tenths from 0.05 %; below, two significant digits (never "0.0 % less").
      sentences.push_back(lb + ": " +
                          percent(p / 100, p >= 0.05 ? PercentDigits::tenths : PercentDigits::two) +
                          " " + less + " " + what + " than " + lo + both + ".");
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
    if (!run.summary.value(key::completed.name(), true))
      sentences.push_back(run.label + " did not complete (" +
                          run.summary.value(key::failure.name(), "") +
                          "): its totals cover t = 0 to " +
                          quantity(run.summary.value(key::final_time.name(), 0.0), "s") + " only.");
    else if (!is_valid(run))
      sentences.push_back(run.label + " is not a valid run (" +
                          run.summary.value(key::failure.name(), "") + ").");
  }
  return sentences;
}

// A closed-loop controller with the plant's own model and continuous control
// on the true state (summaries from before these keys existed included).
bool controller_knows_everything(const RunData& run) {
  const auto& s = run.summary;
  const auto believes = s.find(key::controller_model.name());
  const auto loop = s.find(key::control_loop.name());
  const bool exact_model = believes == s.end() || (believes->is_array() && believes->empty());
  const bool continuous = loop == s.end() || (loop->is_string() && *loop == "continuous");
  return exact_model && continuous;
}

// The runs whose step check puts `metric` below its integration floor
// (step_check.metrics.<metric>.below_floor): a comparison of it would compare
// integration errors.
std::vector<std::string> runs_below_floor(const std::vector<RunData>& runs, const std::string& metric) {
  std::vector<std::string> out;
  for (const RunData& run : runs)
    if (report::below_floor(run, metric)) out.push_back(run.label);
  return out;
}

std::string no_verdict_below_floor(const std::string& what, const std::vector<std::string>& runs) {
  std::string names;
  for (const std::string& r : runs) names += (names.empty() ? "" : ", ") + r;
  return what + ": no verdict. The value of " + names +
         " is below its integration floor (under 10 times its change when the run is refined: "
         "the step check), so it measures the integrator, not the arm; a smaller step or "
         "tolerance would make it a result.";
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

bool all_positive(const Comparison& table, const std::string& path) {
  for (const ComparedMetric& m : table.metrics)
    if (m.path == path) {
      for (const auto& v : m.values)
        if (!v.is_number() || !(v.get<double>() > 0)) return false;
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

bool is_valid(const RunData& run) {
  // Summaries written before validity was checked say only "completed".
  return run.has_summary() &&
         run.summary.value(key::valid.name(), run.summary.value(key::completed.name(), false));
}

std::vector<std::string> verdict(const std::vector<RunData>& runs, const Comparison& table) {
  std::vector<std::string> sentences = failures(runs);
  if (!sentences.empty()) {
    sentences.push_back("No verdict: comparing numbers needs every run to be valid.");
    return sentences;
  }
  // A part resting that the scene does not plan to rest changes what is
  // compared: said before any number.
  for (const RunData& run : runs)
    for (const std::string& rest : unplanned_rests(run))
      sentences.push_back(run.label + ": the table also carried " + rest +
                          "; this run's numbers are those of an arm leaning on that part too.");
  // Energy: what the supply delivered where every run's motors drew some (a
  // positive quantity, so a percentage); else the net energy in, which the
  // motors' feeding back can make negative. Below the integration floor: none.
  const bool drawn = all_positive(table, "energy_final.drawn");
  if (const auto low = runs_below_floor(runs, drawn ? metric::energy_drawn : metric::energy_in);
      !low.empty())
    sentences.push_back(no_verdict_below_floor("Electrical energy", low));
  else if (drawn)
    for (auto& s : smaller_is_better(table, "energy_final.drawn", "less",
                                     "electrical energy drawn from the supply"))
      sentences.push_back(std::move(s));
  else if (all_zero(table, "energy_final.electrical_in"))
    sentences.push_back("No run drew electrical energy (energy_final.electrical_in is 0 in all).");
  else
    for (auto& s :
         smaller_is_better(table, "energy_final.electrical_in", "less", "net electrical energy"))
      sentences.push_back(std::move(s));
  // Accuracy: the RMS hand error of the runs' metrics.
  const std::string accuracy = key::metric_path(metric::hand_error_rms);
  if (std::none_of(table.metrics.begin(), table.metrics.end(),
                   [&](const ComparedMetric& m) { return m.path == accuracy; })) {
    sentences.push_back("Hand accuracy is not compared: no run recorded a hand_error column.");
    return sentences;
  }
  if (const auto low = runs_below_floor(runs, metric::hand_error_rms); !low.empty()) {
    sentences.push_back(no_verdict_below_floor("Hand accuracy", low));
    return sentences;
  }
  std::vector<std::string> errors = smaller_is_better(table, accuracy, "smaller", "RMS hand error");
  if (std::all_of(runs.begin(), runs.end(), controller_knows_everything)) {
    // The feed-forward inverts the plant exactly and sees the true state: what
    // is left of the hand error is the integrator's (docs/experiment.md, "What
    // accuracy costs").
    std::string numbers;
    for (const std::string& e : errors) numbers += (numbers.empty() ? "" : " ") + e;
    sentences.push_back("Hand accuracy: no verdict. In these runs the controller knows the plant "
                        "exactly and sees its true state (controller_model [], control_loop "
                        "continuous), so the hand errors are integration error, not control "
                        "error: " + numbers +
                        " For an accuracy verdict give controller.model or uncertainty: and run "
                        "elbowsim montecarlo.");
    return sentences;
  }
  for (auto& e : errors) sentences.push_back(std::move(e));
  sentences.push_back("One run each: these differences have no confidence interval (elbowsim "
                      "montecarlo gives one).");
  return sentences;
}

Comparison compare_runs(const std::vector<RunData>& runs) {
  Comparison c;
  std::vector<std::vector<Metric>> per_run;
  for (const RunData& run : runs) {
    c.labels.push_back(run.label);
    c.folders.push_back(run.folder.generic_string());
    c.completed.push_back(run.has_summary() && run.summary.value(key::completed.name(), false));
    c.valid.push_back(is_valid(run));
    c.failures.push_back(run.has_summary() ? run.summary.value(key::failure.name(), "")
                                           : "no summary.json");
    // A run that stopped before its first step (its task could not be planned)
    // has no numbers to compare, only zeros in its summary.
    const bool ran =
        c.completed.back() || (run.has_summary() && run.summary.value(key::steps.name(), 0L) > 0);
    per_run.push_back(ran ? run_metrics(run) : std::vector<Metric>());
  }
  add_rows(runs, per_run, c.metrics);
  c.verdict = verdict(runs, c);
  return c;
}

nlohmann::ordered_json comparison_json(const Comparison& c) {
  using Json = nlohmann::ordered_json;
  Json j;
  j["provenance"] = provenance_json();
  j["runs"] = c.labels;
  j["reference"] = c.labels.empty() ? "" : c.labels[0];
  for (const char* key : {"folder", "completed", "valid", "failure"}) j[key] = Json::object();
  for (std::size_t r = 0; r < c.labels.size(); ++r) {
    j["folder"][c.labels[r]] = c.folders[r];
    j["completed"][c.labels[r]] = bool(c.completed[r]);
    j["valid"][c.labels[r]] = bool(c.valid[r]);
    j["failure"][c.labels[r]] = c.failures[r];
  }
  j["verdict"] = c.verdict;
  if (!c.differing_keys.empty()) {  // only compare fills them: a variants' comparison has them in its file
    j["differing_keys"] = Json::object();
    for (const auto& [key, values] : c.differing_keys)
      for (std::size_t r = 0; r < c.labels.size() && r < values.size(); ++r) j["differing_keys"][key][c.labels[r]] = values[r];
  }
  j["metrics"] = Json::array();
  for (const ComparedMetric& m : c.metrics) {
    Json row = {{"path", m.path}, {"unit", m.unit}, {"kind", to_string(m.kind)}};
    for (std::size_t r = 0; r < c.labels.size(); ++r) {
      row["values"][c.labels[r]] = m.values[r];
      row["relative"][c.labels[r]] = m.relative[r] ? Json(*m.relative[r]) : Json();
    }
    row["floor"] = m.floor.value;
    row["floor_basis"] = m.floor.basis;
    row["same"] = m.same;
    j["metrics"].push_back(std::move(row));
  }
  return j;
}

namespace {

// A number as summary.json writes it (shortest round trip); "" for null.
std::string csv_cell(const nlohmann::ordered_json& v) { return v.is_number() ? v.dump() : ""; }

// A CSV field, quoted when it holds a comma, quote or line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

std::string csv_header(const ComparedMetric& m) {
  return csv_field(m.unit.empty() ? m.path : m.path + " [" + m.unit + "]");
}

}  // namespace

void write_comparison_csv(std::ostream& out, const Comparison& c, const std::string& first_header) {
  out << csv_field(first_header) << ",completed,valid";
  for (const ComparedMetric& m : c.metrics) out << ',' << csv_header(m);
  for (const ComparedMetric& m : c.metrics) out << ',' << csv_field(m.path + " rel");
  out << '\n';
  for (std::size_t r = 0; r < c.labels.size(); ++r) {
    out << csv_field(c.labels[r]) << ',' << (c.completed[r] ? "true" : "false") << ','
        << (c.valid[r] ? "true" : "false");
    for (const ComparedMetric& m : c.metrics) out << ',' << csv_cell(m.values[r]);
    for (const ComparedMetric& m : c.metrics)
      out << ',' << (m.relative[r] ? nlohmann::ordered_json(*m.relative[r]).dump() : "");
    out << '\n';
  }
}

void write_sweep_csv(std::ostream& out, const std::string& key,
                     const std::vector<std::string>& values,
                     const std::vector<std::string>& variants, const std::vector<RunData>& runs) {
  const Comparison c = compare_runs(runs);
  out << csv_field(key) << ",variant,completed,valid";
  for (const ComparedMetric& m : c.metrics) out << ',' << csv_header(m);
  out << '\n';
  for (std::size_t r = 0; r < runs.size(); ++r) {
    out << csv_field(values[r]) << ',' << csv_field(variants[r]) << ','
        << (c.completed[r] ? "true" : "false") << ',' << (c.valid[r] ? "true" : "false");
    for (const ComparedMetric& m : c.metrics) out << ',' << csv_cell(m.values[r]);
    out << '\n';
  }
}

}  // namespace elbowsim::report

#include "report/compare_report.hpp"

#include <cmath>
#include <sstream>

#include "engine/recording/number_text.hpp"
#include "report/headline.hpp"
#include "report/html.hpp"
#include "report/plots_aside.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim::report {

namespace {

namespace fs = std::filesystem;
namespace key = summary_key;

std::string cell(const std::string& text, const char* css = "") {
  return std::string("<td") + (*css ? std::string(" class=\"") + css + "\"" : "") + ">" +
         html::escape(text) + "</td>";
}

std::string field(const RunData& run, const nlohmann::ordered_json::json_pointer& path) {
  if (!run.has_summary() || !run.summary.contains(path)) return "—";
  const auto& v = run.summary[path];
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array()) {
    std::string out;
    for (const auto& item : v) out += (out.empty() ? "" : ", ") + item.get<std::string>();
    return out.empty() ? "(none)" : out;
  }
  return html::display_value(v);
}

// One column per run: where each came from and how it ran.
std::string runs_table(const std::vector<RunData>& runs, const fs::path& out) {
  using P = nlohmann::ordered_json::json_pointer;
  const std::pair<const char*, SummaryKey> rows[] = {{"scenario", key::scenario},
                                                     {"description", key::description},
                                                     {"completed", key::completed},
                                                     {"valid", key::valid},
                                                     {"failure", key::failure},
                                                     {"active effects", key::effects},
                                                     {"integrator", key::settings_integrator},
                                                     {"dynamics", key::settings_dynamics},
                                                     {"step [s]", key::settings_step},
                                                     {"duration [s]", key::settings_duration},
                                                     {"steps", key::steps},
                                                     {"wall time [s]", key::wall_seconds}};
  std::string t = "<table id=\"runs\">\n<tr><th>run</th>";
  for (const RunData& run : runs) {
    std::string name = html::escape(run.label);
    if (fs::exists(run.folder / "report.html"))
      name = "<a href=\"" +
             html::escape(fs::relative(run.folder / "report.html", out).generic_string()) + "\">" +
             name + "</a>";
    t += "<th>" + name + "</th>";
  }
  t += "</tr>\n";
  for (const auto& [label, k] : rows) {
    t += "<tr><th scope=\"row\">" + std::string(label) + "</th>";
    for (const RunData& run : runs) t += cell(field(run, P(k.pointer())));
    t += "</tr>\n";
  }
  return t + "</table>\n";
}

// Run `run` against the first: "same" within the noise floor; else "+12.3 %",
// or the difference itself where the first run's value is within the floor
// of 0; settings "differs"; timings a ratio, never a percentage.
std::string relative_text(const ComparedMetric& m, std::size_t run) {
  const auto& v = m.values[run];
  const auto& ref = m.values[0];
  if (v.is_null() || ref.is_null()) return v.is_null() && ref.is_null() ? "same" : "—";
  if (!v.is_number() || !ref.is_number()) return v == ref ? "same" : "differs";
  const double a = ref.get<double>(), b = v.get<double>();
  const bool same = same_within({ref, v}, m.kind, m.floor, m.path);
  switch (m.kind) {
    case MetricKind::setting:
      return same ? "same" : "differs";
    case MetricKind::timing:
      if (same) return m.path == key::wall_seconds.path ? "same (timing noise)" : "same";
      return a != 0 ? "×" + significant(b / a, 3) + " (timing)" : "differs (timing)";
    default:
      break;
  }
  if (same) return "same";
  if (std::abs(a) > m.floor.value && m.relative[run]) {
    // Up to doubling as a percentage; beyond, as a factor ("×8.72").
    if (*m.relative[run] >= 1 && a > 0) return "×" + significant(b / a, 3);
    return percent(*m.relative[run], PercentDigits::three_signed);
  }
  const std::string text = significant(b - a, 3, Sign::always);
  return m.unit.empty() ? text : text + " " + m.unit;
}

std::string floor_text(const ComparedMetric& m) {
  if (m.kind == MetricKind::setting || m.floor.basis == "exact") return "exact";
  if (m.path == key::wall_seconds.path) return m.floor.basis;
  return quantity(m.floor.value, m.unit) + ": " + m.floor.basis;
}

// The metrics of one kind: value per run, each other run against the first,
// and the noise floor the difference was judged by.
std::string metrics_table(const Comparison& c, MetricKind kind, const std::string& id) {
  std::string t = "<table id=\"" + id + "\">\n<tr><th>metric</th><th>unit</th>";
  for (const std::string& label : c.labels) t += "<th>" + html::escape(label) + "</th>";
  for (std::size_t r = 1; r < c.labels.size(); ++r)
    t += "<th>" + html::escape(c.labels[r]) + " vs " + html::escape(c.labels[0]) + "</th>";
  t += "<th>noise floor</th></tr>\n";
  std::size_t rows = 0;
  for (const ComparedMetric& m : c.metrics) {
    if (m.kind != kind) continue;
    ++rows;
    t += std::string(m.same ? "<tr>" : "<tr class=\"differs\">") + "<td><code>" +
         html::escape(m.path) + "</code></td>" + cell(m.unit);
    for (std::size_t r = 0; r < m.values.size(); ++r)
      t += "<td class=\"num\" data-run=\"" + html::escape(c.labels[r]) + "\" data-value=\"" +
           html::exact_value(m.values[r]) + "\">" +
           html::escape(m.values[r].is_null() ? "—" : html::display_value(m.values[r])) + "</td>";
    for (std::size_t r = 1; r < m.values.size(); ++r) {
      const std::string text = relative_text(m, r);
      t += cell(text, text.rfind("same", 0) == 0 ? "num same" : "num differs");
    }
    t += cell(floor_text(m), "meta") + "</tr>\n";
  }
  return rows ? t + "</table>\n" : "";
}

const ComparedMetric* row_of(const Comparison& c, const std::string& path) {
  for (const ComparedMetric& m : c.metrics)
    if (m.path == path) return &m;
  return nullptr;
}

// A headline item's difference: of its own path, or (per joint, per elbow)
// "same" when all its entries are the same, else "differs".
std::string headline_difference(const Comparison& c, const std::string& path, std::size_t run) {
  if (const ComparedMetric* m = row_of(c, path)) return relative_text(*m, run);
  bool any = false, all_same = true;
  for (const ComparedMetric& m : c.metrics)
    if (m.path.rfind(path + ".", 0) == 0) {
      any = true;
      all_same = all_same && relative_text(m, run) == "same";
    }
  return !any ? "—" : all_same ? "same" : "differs";
}

// The first screen after the verdict: each run's headline numbers side by side.
std::string headline_table(const std::vector<RunData>& runs, const Comparison& c) {
  std::vector<const RunData*> pointers;
  for (const RunData& run : runs) pointers.push_back(&run);
  std::string t = "<table class=\"headline\" id=\"headline-table\">\n<tr><th></th>";
  for (const RunData& run : runs) t += "<th>" + html::escape(run.label) + "</th>";
  for (std::size_t r = 1; r < runs.size(); ++r)
    t += "<th>" + html::escape(runs[r].label) + " vs " + html::escape(runs[0].label) + "</th>";
  t += "</tr>\n<tr data-metric=\"valid\"><th scope=\"row\">status</th>";
  for (const RunData& run : runs) {
    const std::string status = validity(run);
    t += "<td class=\"" + std::string(status == "valid" ? "status-valid" : "status-invalid") +
         "\">" + html::escape(status) + "</td>";
  }
  for (std::size_t r = 1; r < runs.size(); ++r) t += "<td></td>";
  t += "</tr>\n";
  // What sets the runs apart: the scenario keys whose values differ, per run.
  t += "<tr data-metric=\"differing_keys\"><th scope=\"row\">scenario keys that differ</th>";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::string keys;
    for (const auto& [key, values] : c.differing_keys)
      keys +=
          (keys.empty() ? "" : "; ") + key + " = " + (values[r].empty() ? "(not set)" : values[r]);
    t += "<td class=\"keys\">" +
         html::escape(c.differing_keys.empty() ? "none (same scenario)" : keys) + "</td>";
  }
  for (std::size_t r = 1; r < runs.size(); ++r) t += "<td></td>";
  t += "</tr>\n";
  for (const HeadlineItem& item : headline_items(pointers)) {
    t += "<tr data-metric=\"" + html::escape(item.path) + "\"><th scope=\"row\">" +
         html::escape(item.label) + "</th>";
    for (const RunData& run : runs)
      t += "<td class=\"value\">" + html::escape(headline_value(run, item)) + "</td>";
    for (std::size_t r = 1; r < runs.size(); ++r) {
      // The other resting parts are a list of names: it differs when the lists read
      // differently (every body's metrics, the planned elbows' too, would say "differs"
      // whenever the elbows rest differently).
      const std::string text =
          item.path == key::contact_bodies.path
              ? (headline_value(runs[r], item) == headline_value(runs[0], item) ? "same"
                                                                                : "differs")
              : headline_difference(c, item.path, r);
      t += cell(text, text.rfind("same", 0) == 0 ? "num same" : "num differs");
    }
    t += "</tr>\n";
  }
  // The step-halving check, where any run has one: how far to trust the differences above.
  bool checked = false;
  for (const RunData& run : runs) checked = checked || run.summary.contains(key::step_check.name());
  if (checked) {
    t += "<tr data-metric=\"step_check\"><th scope=\"row\">accuracy check</th>";
    for (const RunData& run : runs) t += cell(accuracy_check(run));
    for (std::size_t r = 1; r < runs.size(); ++r) t += "<td></td>";
    t += "</tr>\n";
  }
  return t + "</table>\n";
}

std::string notices(const std::vector<RunData>& runs) {
  std::string out;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const RunData& run = runs[k];
    const std::string id = std::to_string(k);
    if (run.has_summary() && run.summary.value(key::completed.name(), true) && !is_valid(run))
      out += html::notice(
          "failure", run.label + " is not a valid run",
          {run.summary.value(key::failure.name(), std::string("(no reason recorded)"))},
          "failure-" + id);
    if (run.has_summary() && !run.summary.value(key::completed.name(), true))
      out += html::notice(
          "failure", run.label + " did not complete",
          {run.summary.value(key::failure.name(), std::string("(no reason recorded)"))},
          "failure-" + id);
    std::vector<std::string> warnings;
    if (run.has_summary() && run.summary.contains(key::warnings.name()))
      for (const auto& w : run.summary[key::warnings.name()])
        warnings.push_back(w.get<std::string>());
    if (!warnings.empty())
      out += html::notice("warnings", run.label + ": warnings", warnings, "warnings-" + id);
    if (!run.problems.empty())
      out += html::notice("problems", run.label + ": missing or unreadable files", run.problems,
                          "problems-" + id);
  }
  return out;
}

std::string figures_of(const FigureSet& figures, const std::string& group) {
  std::string out;
  for (const Figure& f : figures.figures)
    if (f.group == group) out += html::figure(f);
  return out;
}

std::string section(const std::string& id, const std::string& title, const std::string& body) {
  return body.empty()
             ? ""
             : "<section id=\"" + id + "\">\n<h2>" + title + "</h2>\n" + body + "</section>\n";
}

// How differences are judged, under the verdict.
std::string confidence(const Comparison& c) {
  for (const std::string& sentence : c.verdict)
    if (sentence.find("confidence interval") != std::string::npos ||
        sentence.find("No verdict") != std::string::npos)
      return "";
  return "Confidence: one run each, so none: a single pair of runs gives no interval. "
         "elbowsim montecarlo runs the uncertain plant many times and gives the paired ratio "
         "with its 95 % interval.";
}

std::string page(const std::vector<RunData>& runs, const Comparison& c, const FigureSet& figures,
                 const fs::path& out, const fs::path& json, bool video) {
  std::string names;
  for (const std::string& label : c.labels) names += (names.empty() ? "" : " vs ") + label;
  std::string p = html::page_begin("elbowsim comparison: " + comparison_title(runs));
  const std::string scenario =
      runs.front().has_summary() ? runs.front().summary.value(key::scenario.name(), "") : "";
  p += "<header>\n<h1>Comparison: " + html::escape(names) + "</h1>\n<p class=\"meta\">" +
       (scenario.empty() ? "" : "Scenario " + html::escape(scenario) + "; ") +
       std::to_string(runs.size()) + " recorded runs; differences are to " +
       html::escape(c.labels[0]) +
       ", and a difference below its noise floor is shown as "
       "<em>same</em>. Numbers in <a href=\"" +
       html::escape(fs::relative(json, out).generic_string()) + "\">" +
       html::escape(fs::relative(json, out).generic_string()) + "</a>.</p>\n</header>\n";
  std::vector<std::string> verdict = c.verdict;
  if (const std::string conf = confidence(c); !conf.empty()) verdict.push_back(conf);
  p += html::notice("verdict", "Verdict", verdict, "verdict") + notices(runs);
  p += section("headline", "The runs side by side", headline_table(runs, c));
  std::string nav = "<a href=\"#headline\">Side by side</a>";
  if (!figures_of(figures, "hand_path").empty()) nav += " · <a href=\"#hand-path\">Hand paths</a>";
  if (!figures_of(figures, "energy").empty()) nav += " · <a href=\"#energy\">Energy</a>";
  if (video) nav += " · <a href=\"#video\">Video</a>";
  p += "<nav class=\"meta\">" + nav +
       " · <a href=\"#plots\">More plots</a> · <a href=\"#runs-section\">Runs</a>"
       " · <a href=\"#metrics-section\">All metrics</a></nav>\n";
  p += section("hand-path", "Hand paths", figures_of(figures, "hand_path"));
  p += section("energy", "Where the energy went", figures_of(figures, "energy"));
  if (video)
    p += "<section id=\"video\">\n<h2>Video</h2>\n<video src=\"video.mp4\" controls "
         "preload=\"metadata\" width=\"960\">video.mp4</video>\n<p class=\"meta\">The runs side by "
         "side, each panel labelled with its run.</p>\n</section>\n";
  std::string more = figures_of(figures, "");
  for (const std::string& s : figures.skipped)
    more += "<p class=\"meta\">Not plotted: " + html::escape(s) + "</p>\n";
  p += section("plots", "More plots", more);
  p += "<section id=\"runs-section\">\n<h2>Runs</h2>\n" + runs_table(runs, out) + "</section>\n";
  p += "<section id=\"metrics-section\">\n<h2>All metrics</h2>\n<h3>Results</h3>\n" +
       metrics_table(c, MetricKind::result, "comparison-metrics") +
       "<h3>Numerics: how well the integration went</h3>\n" +
       metrics_table(c, MetricKind::numerics, "comparison-numerics") +
       "<h3>Timing and cost: measurements of the computer, not results</h3>\n<p class=\"meta\">One "
       "measurement each on a shared machine; wall-time ratios within 1.25 are noise.</p>\n" +
       metrics_table(c, MetricKind::timing, "comparison-timing") +
       "<h3>Settings and initial state</h3>\n" +
       metrics_table(c, MetricKind::setting, "comparison-settings");
  return p + "</section>\n" + html::page_end();
}

}  // namespace

std::pair<fs::path, fs::path> write_comparison_tables(const Comparison& comparison,
                                                      const ComparisonTables& tables) {
  const fs::path json = tables.folder / "comparison.json", csv = tables.folder / "comparison.csv";
  html::write_file(json, comparison_json(comparison).dump(2) + "\n");
  std::ostringstream text;
  write_comparison_csv(text, comparison, tables.first_header);
  html::write_file(csv, text.str());
  return {json, csv};
}

ComparisonFiles write_comparison_report(
    const std::vector<RunData>& runs, const fs::path& out, const ComparisonTables& tables,
    bool video, const std::vector<std::pair<std::string, std::vector<std::string>>>& differing) {
  fs::create_directories(out);
  ComparisonTables where = tables;
  if (where.folder.empty()) where.folder = out;
  ComparisonFiles files;
  files.comparison = compare_runs(runs);
  files.comparison.differing_keys = differing;
  std::tie(files.json, files.csv) = write_comparison_tables(files.comparison, where);
  PlotsAside aside(out);
  files.figures = write_comparison_plots(runs, out);
  files.html = out / "report.html";
  html::write_file(files.html, page(runs, files.comparison, files.figures, out, files.json, video));
  aside.keep();
  return files;
}

}  // namespace elbowsim::report

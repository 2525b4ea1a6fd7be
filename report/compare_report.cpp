#include "report/compare_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/html.hpp"

namespace elbowsim::report {

namespace {

namespace fs = std::filesystem;

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
  const std::pair<const char*, const char*> rows[] = {{"scenario", "/scenario"},
                                                      {"description", "/description"},
                                                      {"completed", "/completed"},
                                                      {"valid", "/valid"},
                                                      {"failure", "/failure"},
                                                      {"active effects", "/effects"},
                                                      {"integrator", "/settings/integrator"},
                                                      {"dynamics", "/settings/dynamics"},
                                                      {"step [s]", "/settings/step"},
                                                      {"duration [s]", "/settings/duration"},
                                                      {"steps", "/steps"},
                                                      {"wall time [s]", "/wall_seconds"}};
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
  for (const auto& [label, pointer] : rows) {
    t += "<tr><th scope=\"row\">" + std::string(label) + "</th>";
    for (const RunData& run : runs) t += cell(field(run, P(pointer)));
    t += "</tr>\n";
  }
  return t + "</table>\n";
}

// "+12.3 %", "same"; for flags and missing values "same", "differs" or "—".
std::string relative_text(const ComparedMetric& m, std::size_t run) {
  const std::optional<double>& r = m.relative[run];
  if (!r)
    return m.values[run].is_null() || m.values[0].is_null() ? "—"
           : m.values[run] == m.values[0]                   ? "same"
                                                            : "differs";
  if (*r == 0) return "same";
  char text[32];
  std::snprintf(text, sizeof text, "%+.3g %%", 100 * *r);
  return text;
}

bool differs(const ComparedMetric& m) {
  for (const auto& v : m.values)
    if (v != m.values[0]) return true;
  return false;
}

// Every metric: value per run, then the relative difference of each other run to the first.
std::string metrics_table(const Comparison& c) {
  std::string t = "<table id=\"comparison-metrics\">\n<tr><th>metric</th><th>unit</th>";
  for (const std::string& label : c.labels) t += "<th>" + html::escape(label) + "</th>";
  for (std::size_t r = 1; r < c.labels.size(); ++r)
    t += "<th>" + html::escape(c.labels[r]) + " vs " + html::escape(c.labels[0]) + "</th>";
  t += "</tr>\n";
  for (const ComparedMetric& m : c.metrics) {
    t += std::string(differs(m) ? "<tr class=\"differs\">" : "<tr>") + "<td><code>" +
         html::escape(m.path) + "</code></td>" + cell(m.unit);
    for (std::size_t r = 0; r < m.values.size(); ++r)
      t += "<td class=\"num\" data-run=\"" + html::escape(c.labels[r]) + "\" data-value=\"" +
           html::exact_value(m.values[r]) + "\">" +
           html::escape(m.values[r].is_null() ? "—" : html::display_value(m.values[r])) + "</td>";
    for (std::size_t r = 1; r < m.values.size(); ++r)
      t += cell(relative_text(m, r),
                m.relative[r] && std::abs(*m.relative[r]) >= 0.005 ? "num differs" : "num");
    t += "</tr>\n";
  }
  return t + "</table>\n";
}

std::string notices(const std::vector<RunData>& runs) {
  std::string out;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const RunData& run = runs[k];
    const std::string id = std::to_string(k);
    if (run.has_summary() && run.summary.value("completed", true) && !is_valid(run))
      out += html::notice("failure", run.label + " is not a valid run",
                          {run.summary.value("failure", std::string("(no reason recorded)"))},
                          "failure-" + id);
    if (run.has_summary() && !run.summary.value("completed", true))
      out += html::notice("failure", run.label + " did not complete",
                          {run.summary.value("failure", std::string("(no reason recorded)"))},
                          "failure-" + id);
    std::vector<std::string> warnings;
    if (run.has_summary() && run.summary.contains("warnings"))
      for (const auto& w : run.summary["warnings"]) warnings.push_back(w.get<std::string>());
    if (!warnings.empty())
      out += html::notice("warnings", run.label + ": warnings", warnings, "warnings-" + id);
    if (!run.problems.empty())
      out += html::notice("problems", run.label + ": missing or unreadable files", run.problems,
                          "problems-" + id);
  }
  return out;
}

std::string page(const std::vector<RunData>& runs, const Comparison& c, const FigureSet& figures,
                 const fs::path& out, const fs::path& json) {
  std::string names;
  for (const std::string& label : c.labels) names += (names.empty() ? "" : " vs ") + label;
  std::string p = html::page_begin("elbowsim comparison: " + names);
  p += "<header>\n<h1>Comparison: " + html::escape(names) + "</h1>\n<p class=\"meta\">" +
       std::to_string(runs.size()) + " recorded runs; relative differences are to " +
       html::escape(c.labels[0]) + ". Numbers in <a href=\"" +
       html::escape(fs::relative(json, out).generic_string()) + "\">" +
       html::escape(fs::relative(json, out).generic_string()) + "</a>.</p>\n</header>\n";
  p += html::notice("verdict", "Verdict", c.verdict, "verdict") + notices(runs);
  p += "<section id=\"runs-section\">\n<h2>Runs</h2>\n" + runs_table(runs, out) + "</section>\n";
  p += "<section id=\"metrics-section\">\n<h2>Metrics</h2>\n" + metrics_table(c) + "</section>\n";
  p += "<section id=\"plots\">\n<h2>Plots</h2>\n";
  for (const Figure& f : figures.figures) p += html::figure(f);
  for (const std::string& s : figures.skipped)
    p += "<p class=\"meta\">Not plotted: " + html::escape(s) + "</p>\n";
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

ComparisonFiles write_comparison_report(const std::vector<RunData>& runs, const fs::path& out,
                                        const ComparisonTables& tables) {
  fs::create_directories(out);
  ComparisonTables where = tables;
  if (where.folder.empty()) where.folder = out;
  ComparisonFiles files;
  files.comparison = compare_runs(runs);
  std::tie(files.json, files.csv) = write_comparison_tables(files.comparison, where);
  files.figures = write_comparison_plots(runs, out);
  files.html = out / "report.html";
  html::write_file(files.html, page(runs, files.comparison, files.figures, out, files.json));
  return files;
}

}  // namespace elbowsim::report

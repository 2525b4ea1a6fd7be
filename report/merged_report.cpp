// report.html of a merged study (report/merged_study.hpp): what ran and what
// failed, each headline metric against every numeric swept key, the table.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>

#include "report/html.hpp"
#include "report/merged_study.hpp"
#include "report/plot/plot.hpp"
#include "report/plots_aside.hpp"
#include "report/statistics.hpp"

namespace elbowsim::report {

namespace {

// The value of column `j` of every row as a number; false if one is not.
bool numeric_column(const MergedStudy& s, std::size_t j) {
  for (const MergedRow& r : s.rows) {
    const std::string& v = r.values[j];
    char* end = nullptr;
    std::strtod(v.c_str(), &end);
    if (v.empty() || *end) return false;
  }
  return !s.rows.empty();
}

// Which line a point belongs to against column j: its variant and the
// values of the other columns ("elbow_on, duration=2").
std::string line_of(const MergedStudy& s, const MergedRow& row, const std::string& variant,
                    std::size_t j) {
  std::string label = variant.empty() ? "run" : variant;
  for (std::size_t k = 0; k < s.columns.size(); ++k)
    if (k != j) label += ", " + s.columns[k] + "=" + row.values[k];
  return label;
}

// Metric h of every point against column j: a marked line per variant and
// level of the other columns, with the 95 % interval of the mean as a bar
// when there are draws.
plot::LinePlot against(const MergedStudy& s, const std::vector<MergedPoint>& points, std::size_t h,
                       std::size_t j) {
  const std::string& path = headline_paths()[h];
  const std::string unit = metric_unit(path);
  plot::LinePlot p;
  p.title = path.substr(path.find('.') + 1) + " against " + s.columns[j] +
            (s.draws > 0 ? " (mean over draws)" : "");
  p.x = plot::linear_axis(s.columns[j], "");
  p.y = plot::log_axis(path.substr(path.find('.') + 1), unit);
  std::vector<std::string> order;
  std::map<std::string, std::pair<plot::Series, plot::Series>> lines;  // label -> mean, bars
  for (const MergedPoint& pt : points) {
    const MergedRow& row = s.rows[pt.row];
    const std::string label = line_of(s, row, pt.variant, j);
    if (!lines.count(label)) order.push_back(label);
    auto& [line, bars] = lines[label];
    line.label = label;
    line.markers = true;
    const double x = std::strtod(row.values[j].c_str(), nullptr);
    const std::vector<double>& y = pt.values[h];
    line.x.push_back(x);
    line.y.push_back(y.empty() ? NAN : mean(y));
    if (s.draws > 0 && !y.empty())
      if (const Estimate e = headline_estimate(y, h); e.ci) {
        bars.x.insert(bars.x.end(), {x, x, NAN});
        bars.y.insert(bars.y.end(), {e.ci->low, e.ci->high, NAN});
      }
  }
  for (std::size_t k = 0; k < order.size(); ++k) {
    auto& [line, bars] = lines[order[k]];
    line.color = bars.color = plot::palette(static_cast<int>(k));
    bars.width = 1.2;
    p.series.push_back(line);
    if (!bars.x.empty()) p.series.push_back(bars);
  }
  return p;
}

std::string state_notice(const MergedStudy& s) {
  long done = 0, failed = 0, missing = 0;
  std::vector<std::string> problems;
  for (const MergedRow& r : s.rows) {
    done += r.status == "done";
    failed += r.status == "failed";
    missing += r.status == "missing";
    if (r.status == "failed")
      problems.push_back(r.folder + (r.variant.empty() ? "" : " " + r.variant) + ": " + r.failure);
    if (r.status == "missing")
      problems.push_back(r.folder + (r.variant.empty() ? "" : " " + r.variant) + ": not run yet");
  }
  std::string out = "<p id=\"state\">" + std::to_string(s.rows.size()) +
                    " runs: " + std::to_string(done) + " done, " + std::to_string(failed) +
                    " failed, " + std::to_string(missing) + " missing.</p>\n";
  if (!problems.empty())
    out += html::notice("failure", "Runs that failed or are missing", problems, "failures", 12);
  return out;
}

std::string row_table(const MergedStudy& s, const std::filesystem::path& out) {
  std::string t = "<h2>Runs</h2>\n<table id=\"runs\"><thead><tr><th>case</th>";
  for (const std::string& c : s.columns) t += "<th>" + html::escape(c) + "</th>";
  if (s.draws > 0) t += "<th>draw</th>";
  t += "<th>variant</th><th>status</th>";
  for (const std::string& h : headline_paths()) {
    const std::string unit = metric_unit(h);
    t += "<th>" + html::escape(h.substr(h.find('.') + 1)) +
         (unit.empty() ? "" : " [" + unit + "]") + "</th>";
  }
  t += "</tr></thead><tbody>\n";
  for (const MergedRow& r : s.rows) {
    const std::string link = r.run.empty() ? "" : std::filesystem::relative(r.run, out).string();
    t += "<tr><td>" +
         (link.empty()
              ? html::escape(r.folder)
              : "<a href=\"" + html::escape(link) + "/\">" + html::escape(r.folder) + "</a>") +
         "</td>";
    for (const std::string& v : r.values) t += "<td>" + html::escape(v) + "</td>";
    if (s.draws > 0) t += "<td class=\"num\">" + std::to_string(r.draw) + "</td>";
    t += "<td>" + html::escape(r.variant) + "</td><td>" + html::escape(r.status) + "</td>";
    for (const std::string& h : headline_paths()) {
      const Metric* m = find_metric(r.metrics, h);
      t += "<td class=\"num\">" + (m ? html::display_value(m->value) : std::string("—")) + "</td>";
    }
    t += "</tr>\n";
  }
  return t + "</tbody></table>\n";
}

}  // namespace

std::filesystem::path write_merged_report(const MergedStudy& s, const std::filesystem::path& out) {
  PlotsAside aside(out);
  std::filesystem::create_directories(out / "plots");
  const std::vector<MergedPoint> points = merged_points(s);
  std::string figures;
  for (std::size_t j = 0; j < s.columns.size(); ++j) {
    if (!numeric_column(s, j)) continue;
    for (const std::size_t h : {std::size_t(2), std::size_t(0)}) {  // RMS hand error, energy in
      const plot::LinePlot p = against(s, points, h, j);
      std::string column;
      for (const char c : s.columns[j])
        column += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      const std::string file = "plots/" + headline_paths()[h].substr(8) + "_vs_" +
                               std::to_string(j) + "_" + column + ".png";
      plot::write_png(p, out / file);
      figures += html::figure(
          {file, p.title,
           s.draws > 0 ? "The mean over each point's valid draws, a bar over its 95 % "
                         "bootstrap interval (given from " +
                             std::to_string(kMinIntervalValues) +
                             " valid draws); one line per variant and level of the other keys."
                       : "One marked line per variant and level of the other keys.",
           p.width, p.height});
    }
  }
  std::string page = html::page_begin("Study: " + s.name);
  page += "<h1>Study " + html::escape(s.name) + ": " + std::to_string(s.rows.size()) + " runs of " +
          html::escape(s.scenario) + "</h1>\n";
  page += state_notice(s);
  std::string keys;
  for (const std::string& c : s.columns) keys += (keys.empty() ? "" : ", ") + c;
  page += html::info_table(
      {{"scenario file", s.scenario},
       {"swept", keys.empty() ? "—" : keys},
       {"draws per point", s.draws > 0 ? std::to_string(s.draws) : "none"},
       {"tables", "table.csv (every run)" +
                      std::string(s.draws > 0 ? ", points.csv (means and intervals)" : "")}});
  if (!figures.empty()) page += "<h2>Against the swept keys</h2>\n" + figures;
  page += row_table(s, out);
  page += html::page_end();
  html::write_file(out / "report.html", page);
  aside.keep();
  return out / "report.html";
}

}  // namespace elbowsim::report

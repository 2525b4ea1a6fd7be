#include "report/sensitivity_report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "engine/recording/metrics.hpp"
#include "engine/recording/number_text.hpp"
#include "report/html.hpp"
#include "report/plot/plot.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

// The compared ratio as a title names it.
std::string short_name(const std::string& metric) {
  if (metric == metric::energy_drawn) return "Energy drawn";
  if (metric == metric::hand_error_rms) return "RMS hand error";
  return metric;
}

double number_or_nan(const Json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : std::nan("");
}

// Where an end holds its factor: "−10 %", or a range's value "−0.1001".
std::string end_value(const Json& factor, const char* end) {
  const double value = number_or_nan(factor[end], "value");
  const bool relative = factor.value("law", "").rfind("range", 0) != 0;
  std::string at = relative ? significant(100 * std::abs(value), 3) + " %" : significant(std::abs(value), 4);
  if (value < 0) at = "−" + at;
  else if (relative && value > 0) at = "+" + at;
  return at;
}

// "−10 %: 0.64": the chart's label of an end.
std::string end_text(const Json& factor, const char* end) {
  const double ratio = number_or_nan(factor[end], "ratio");
  return end_value(factor, end) + ": " + (std::isfinite(ratio) ? significant(ratio, 3) : "no estimate");
}

plot::Tornado tornado_of(const Json& m) {
  plot::Tornado t;
  const std::string a = m.value("a", ""), b = m.value("b", "");
  t.title = short_name(m.value("metric", "")) + ", " + a + " ÷ " + b + ": each parameter alone at its ends";
  t.x = plot::linear_axis("paired ratio " + a + " ÷ " + b + " (geometric mean over the draws)", "");
  t.centre = number_or_nan(m["nominal"], "ratio");
  t.reference = 1.0;
  t.centre_label = "every parameter drawn";
  t.reference_label = "1: the verdict flips";
  t.low_label = "held at its low end";
  t.high_label = "held at its high end";
  for (const Json& f : m["factors"])
    t.rows.push_back({f.value("given", ""), number_or_nan(f["low"], "ratio"), number_or_nan(f["high"], "ratio"),
                      end_text(f, "low"), end_text(f, "high")});
  t.empty_message = "no estimate with every parameter drawn";
  return t;
}

std::string cell(const Json& point) {
  std::string out = "—";
  if (point.contains("ratio")) {
    out = significant(point["ratio"].get<double>(), 3);
    if (point.contains("ci95"))
      out += " (" + significant(point["ci95"][0].get<double>(), 3) + "–" +
             significant(point["ci95"][1].get<double>(), 3) + ")";
  }
  return out + ", " + point.value("outcome", "no verdict");
}

std::string table(const Json& m) {
  std::string out =
      "<table class=\"sensitivity\"><thead><tr><th>rank</th><th>parameter</th><th>law</th>"
      "<th>low end</th><th>high end</th><th>swing (ln)</th><th>effect</th></tr></thead><tbody>\n";
  out += "<tr><td></td><td colspan=\"2\">every parameter drawn</td><td colspan=\"2\" class=\"num\">" +
         html::escape(cell(m["nominal"])) + "</td><td></td><td></td></tr>\n";
  int rank = 0;
  for (const Json& f : m["factors"]) {
    out += "<tr><td class=\"num\">" + std::to_string(++rank) + "</td><td>" + html::escape(f.value("given", "")) +
           "</td><td>" + html::escape(f.value("law", "")) + "</td>";
    for (const char* end : {"low", "high"})
      out += "<td class=\"num\">" + html::escape(end_value(f, end) + ": " + cell(f[end])) + "</td>";
    out += "<td class=\"num\">" + significant(f.value("swing", 0.0), 3) + "</td><td data-effect=\"" +
           html::escape(f.value("effect", "")) + "\">" + html::escape(f.value("effect", "")) + "</td></tr>\n";
  }
  return out + "</tbody></table>\n";
}

}  // namespace

void write_sensitivity_plots(const std::filesystem::path& folder) {
  const Json doc = html::read_json(folder / "sensitivity.json");
  std::filesystem::create_directories(folder / "plots");
  for (const Json& m : doc["metrics"])
    plot::write_png(tornado_of(m), folder / "plots" / ("tornado_" + m.value("metric", "") + ".png"));
}

void write_sensitivity_report(const std::filesystem::path& folder) {
  const Json doc = html::read_json(folder / "sensitivity.json");
  const std::string name = doc.value("scenario", std::string());
  std::string page = html::page_begin("Sensitivity: " + name);
  page += "<h1>What changes the verdict: " + html::escape(name) +
          (doc.contains("case") ? " " + html::escape(doc["case"].get<std::string>()) : "") + "</h1>\n";
  std::vector<std::string> verdict;
  for (const Json& m : doc["metrics"])
    for (const Json& line : m["sentences"]) verdict.push_back(line.get<std::string>());
  page += html::notice("verdict", "Verdicts and what changes them", verdict, "verdict");
  std::string points;
  for (const Json& p : doc["points"])
    points += (points.empty() ? "" : "; ") + p.value("what", "") + " (points/" + p.value("point", "") + "/)";
  page += html::info_table({{"scenario file", doc.value("file", "")},
                            {"draws per point", std::to_string(doc.value("samples", 0)) + " (seed " +
                                                    std::to_string(doc.value("seed", 0UL)) +
                                                    "), the same draws at every point"},
                            {"held at", doc.value("held_at", "")},
                            {"points", points}});
  for (const Json& m : doc["metrics"]) {
    const plot::Tornado t = tornado_of(m);
    page += "<h2>" + html::escape(m.value("what", "")) + "</h2>\n";
    page += html::figure({"plots/tornado_" + m.value("metric", "") + ".png", t.title,
                          "Each bar runs from the paired ratio with every parameter drawn (solid line) to "
                          "the ratio with one parameter held at one end of its range; first the rows that change "
                          "the verdict, then by swing, "
                          "largest first. Across the dashed line at 1 the verdict flips.",
                          t.width, plot::tornado_height(t.rows.size())});
    page += table(m);
  }
  page += html::page_end();
  html::write_file(folder / "report.html", page);
}

}  // namespace elbowsim::report

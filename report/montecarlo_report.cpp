#include "report/montecarlo_report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "report/html.hpp"
#include "report/plot/plot.hpp"
#include "report/plots_aside.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

std::vector<double> numbers(const Json& array) {
  std::vector<double> out;
  for (const Json& v : array) out.push_back(v.is_number() ? v.get<double>() : std::nan(""));
  return out;
}

// Empirical CDF of each variant's values of `metric` (valid draws).
plot::LinePlot ecdf(const Json& doc, const std::string& metric, const std::string& title,
                    const plot::Axis& x) {
  plot::LinePlot p;
  p.title = title;
  p.x = x;
  p.y = plot::linear_axis("share of draws at or below", "");
  p.y.min = 0;
  p.y.max = 1;
  int k = 0;
  for (const auto& [variant, per_metric] : doc["draws"].items()) {
    std::vector<double> v = numbers(per_metric.value(metric, Json::array()));
    v.erase(std::remove_if(v.begin(), v.end(), [](double y) { return !std::isfinite(y); }),
            v.end());
    std::sort(v.begin(), v.end());
    plot::Series s;
    s.label = variant;
    s.color = plot::palette(k++);
    const double n = static_cast<double>(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {  // a staircase
      s.x.push_back(v[i]);
      s.y.push_back(static_cast<double>(i) / n);
      s.x.push_back(v[i]);
      s.y.push_back(static_cast<double>(i + 1) / n);
    }
    p.series.push_back(s);
  }
  return p;
}

// Energy against hand error, one marker per draw and variant.
plot::LinePlot scatter(const Json& doc) {
  plot::LinePlot p;
  p.title = "Energy against hand error, per draw";
  p.x = plot::linear_axis("electrical energy in", "J");
  p.y = plot::log_axis("RMS hand error", "m");
  int k = 0;
  for (const auto& [variant, per_metric] : doc["draws"].items()) {
    const std::vector<double> e = numbers(per_metric.value("energy_in", Json::array()));
    const std::vector<double> h = numbers(per_metric.value("hand_error_rms", Json::array()));
    plot::Series s;
    s.label = variant;
    s.color = plot::palette(k++);
    s.markers = true;
    for (std::size_t i = 0; i < std::min(e.size(), h.size()); ++i) {
      s.x.insert(s.x.end(), {e[i], std::nan("")});  // NaN between points: no line
      s.y.insert(s.y.end(), {h[i], std::nan("")});
    }
    p.series.push_back(s);
  }
  return p;
}

std::string fmt(double x) { return html::display_value(Json(x)); }

// object[key] as a number; NaN when missing or null (a NaN written to JSON
// reads back as null: a floor whose nominal run was invalid).
double number(const Json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : std::nan("");
}

std::string interval(const Json& ci) {
  if (!ci.is_array() || ci.size() != 2 || !ci[0].is_number() || !ci[1].is_number()) return "—";
  return fmt(ci[0].get<double>()) + " – " + fmt(ci[1].get<double>());
}

std::string metrics_section(const Json& doc) {
  std::string out =
      "<h2>Metrics per variant (valid draws)</h2>\n<table id=\"mc-metrics\"><thead><tr>"
      "<th>variant</th><th>metric</th><th>unit</th><th>valid draws</th><th>mean</th>"
      "<th>95 % CI of the mean</th><th>median</th></tr></thead><tbody>\n";
  for (const auto& [variant, metrics] : doc["metrics"].items())
    for (const auto& [name, m] : metrics.items())
      out += "<tr><td>" + html::escape(variant) + "</td><td>" + html::escape(name) + "</td><td>" +
             html::escape(m.value("unit", "")) + "</td><td>" + std::to_string(m.value("valid", 0)) +
             "</td><td>" + fmt(number(m, "mean")) + "</td><td>" + interval(m["ci95"]) +
             "</td><td>" + fmt(number(m, "median")) + "</td></tr>\n";
  return out + "</tbody></table>\n";
}

std::string pairs_section(const Json& doc) {
  std::string out =
      "<h2>Paired comparison (same draws)</h2>\n<table id=\"mc-pairs\"><thead><tr>"
      "<th>A / B</th><th>metric</th><th>pairs</th><th>ratio A/B (geometric mean)</th>"
      "<th>95 % CI</th><th>A below B in</th></tr></thead><tbody>\n";
  for (const Json& p : doc["pairs"])
    for (const char* metric : {"energy_in", "hand_error_rms"}) {
      if (!p.contains(metric)) continue;
      const Json& r = p[metric];
      out += "<tr><td>" + html::escape(p.value("a", "") + " / " + p.value("b", "")) + "</td><td>" +
             metric + "</td><td>" + std::to_string(r.value("pairs", 0)) + "</td><td>" +
             fmt(number(r, "ratio")) + "</td><td>" + interval(r["ci95"]) + "</td><td>" +
             fmt(100 * number(r, "win_rate")) + " % of draws</td></tr>\n";
    }
  return out + "</tbody></table>\n";
}

// What was drawn, and how; the controller keeps the nominal values.
std::string parameters_section(const Json& doc) {
  std::string out =
      "<h2>Uncertain plant parameters</h2>\n<p>Each draw changes these in the "
      "plant only; the controller plans with the nominal values.</p>\n"
      "<table id=\"mc-parameters\"><thead><tr><th>key</th><th>law</th>"
      "<th>nominal</th></tr></thead><tbody>\n";
  for (const Json& p : doc.value("parameters", Json::array())) {
    const std::string law = p.value("law", "");
    std::string spread;
    if (law == "range" && p.contains("range"))
      spread = "uniform in [" + fmt(p["range"][0].get<double>()) + ", " +
               fmt(p["range"][1].get<double>()) + "]";
    else
      spread = law + " ±" + fmt(100 * p.value("spread", 0.0)) + " %" +
               (law == "normal" ? " (σ, truncated at 3σ)" : "");
    std::string nominal;
    const Json nominals = p.value("nominal", Json::object());  // kept: items() does not own it
    for (const auto& [variant, value] : nominals.items())
      nominal += (nominal.empty() ? "" : ", ") + variant + ": " + html::display_value(value);
    out += "<tr><td>" + html::escape(p.value("key", "")) + "</td><td>" + html::escape(spread) +
           "</td><td>" + html::escape(nominal) + "</td></tr>\n";
  }
  return out + "</tbody></table>\n";
}

}  // namespace

void write_montecarlo_report(const std::filesystem::path& folder) {
  const Json doc = html::read_json(folder / "montecarlo.json");
  PlotsAside aside(folder);
  std::filesystem::create_directories(folder / "plots");
  std::vector<Figure> figures;
  auto add = [&](const plot::LinePlot& p, const std::string& file, const std::string& caption) {
    plot::write_png(p, folder / "plots" / file);
    figures.push_back({"plots/" + file, p.title, caption, p.width, p.height});
  };
  add(ecdf(doc, "hand_error_rms", "RMS hand error over the draws",
           plot::log_axis("RMS hand error", "m")),
      "ecdf_hand_error.png",
      "Empirical distribution of each variant's RMS hand error (valid draws).");
  add(ecdf(doc, "energy_in", "Electrical energy over the draws",
           plot::linear_axis("electrical energy in", "J")),
      "ecdf_energy.png",
      "Empirical distribution of each variant's electrical energy in (valid draws).");
  add(scatter(doc), "energy_vs_hand_error.png",
      "Each draw of each variant: electrical energy in against RMS hand error.");

  std::vector<std::string> verdict;
  for (const Json& line : doc.value("verdict", Json::array()))
    verdict.push_back(line.get<std::string>());
  std::string page = html::page_begin("Monte Carlo: " + doc.value("scenario", std::string()));
  page +=
      "<h1>Monte Carlo study: " + html::escape(doc.value("scenario", std::string())) + "</h1>\n";
  page += html::notice("verdict", "Verdict", verdict, "verdict");
  std::vector<std::string> invalid;
  for (const Json& d : doc.value("invalid", Json::array()))
    invalid.push_back("draw " + std::to_string(d.value("draw", -1)) + ", " +
                      d.value("variant", "") + ": " + d.value("failure", ""));
  if (!invalid.empty())
    page += html::notice(
        "failure", std::to_string(invalid.size()) + " invalid runs (left out of the statistics)",
        invalid, "invalid");
  std::vector<std::pair<std::string, std::string>> rows = {
      {"scenario file", doc.value("file", "")},
      {"draws", std::to_string(doc.value("samples", 0)) + " (seed " +
                    std::to_string(doc.value("seed", 0UL)) + "), each applied to every variant"},
      {"uncertain parameters", std::to_string(doc["parameters"].size())}};
  for (const auto& [variant, f] : doc["accuracy_floor"].items())
    rows.push_back({"accuracy floor, " + variant,
                    "RMS hand error " + fmt(number(f, "hand_error_rms_step")) + " m at step " +
                        fmt(number(f, "step")) + " s, " +
                        fmt(number(f, "hand_error_rms_half_step")) + " m at half of it: floor " +
                        fmt(number(f, "floor")) + " m"});
  page += html::info_table(rows);
  page += metrics_section(doc) + pairs_section(doc) + parameters_section(doc);
  page += "<h2>Distributions</h2>\n";
  for (const Figure& f : figures) page += html::figure(f);
  page += html::page_end();
  html::write_file(folder / "report.html", page);
  aside.keep();
}

}  // namespace elbowsim::report

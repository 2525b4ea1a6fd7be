#include "report/montecarlo_report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "engine/recording/metrics.hpp"
#include "engine/recording/number_text.hpp"
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

// The energy the plots show: drawn from the supply (what the ratio compares)
// when the runs have motors, else the net energy in.
struct EnergyShown {
  std::string metric, label;
};
EnergyShown energy_shown(const Json& doc) {
  for (const auto& [variant, per_metric] : doc["draws"].items())
    if (per_metric.contains(metric::energy_drawn))
      return {metric::energy_drawn, "electrical energy drawn from the supply"};
  return {metric::energy_in, "net electrical energy in"};
}

// Energy against hand error, one marker per draw and variant.
plot::LinePlot scatter(const Json& doc) {
  const EnergyShown energy = energy_shown(doc);
  plot::LinePlot p;
  p.title = "Energy against hand error, per draw";
  p.x = plot::linear_axis(energy.label, "J");
  p.y = plot::log_axis("RMS hand error", "m");
  int k = 0;
  for (const auto& [variant, per_metric] : doc["draws"].items()) {
    const std::vector<double> e = numbers(per_metric.value(energy.metric, Json::array()));
    const std::vector<double> h = numbers(per_metric.value(metric::hand_error_rms, Json::array()));
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

// object[key] as a number; NaN when missing or null (a NaN written to JSON
// reads back as null: a floor whose nominal run was invalid).
double number(const Json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : std::nan("");
}

// "1.80 J to 2.03 J" (a ratio's "0.113–0.130"), or why there is none.
std::string interval(const Json& ci, const std::string& unit, const std::string& why) {
  if (!ci.is_array() || ci.size() != 2 || !ci[0].is_number() || !ci[1].is_number())
    return why.empty() ? "—" : "none: " + why;
  return quantity(ci[0].get<double>(), unit) + (unit.empty() ? "–" : " to ") +
         quantity(ci[1].get<double>(), unit);
}

std::string draw_list(const Json& draws) {
  std::string out;
  for (const Json& d : draws) out += (out.empty() ? "" : ", ") + d.dump();
  return out.empty() ? "" : " (draws " + out + ")";
}

std::string metrics_section(const Json& doc) {
  std::string out =
      "<h2>Metrics per variant (valid draws)</h2>\n<p>Means with their 95 % BCa bootstrap "
      "intervals (percentiles of resampled means, corrected for bias and skew): the interval of "
      "a metric that is never negative never is either; the net energy in is negative when the "
      "motors feed back more than they draw. No interval below " +
      std::to_string(doc.value("min_interval_draws", 0)) +
      " valid draws.</p>\n<table id=\"mc-metrics\"><thead><tr>"
      "<th>variant</th><th>metric</th><th>valid draws</th><th>mean</th>"
      "<th>95 % CI of the mean</th><th>median</th></tr></thead><tbody>\n";
  // A study whose every run was invalid has no metrics.
  const Json all = doc.value("metrics", Json::object());  // kept: items() does not own it
  for (const auto& [variant, metrics] : all.items())
    for (const auto& [name, m] : metrics.items()) {
      const std::string unit = m.value("unit", "");
      out += "<tr><td>" + html::escape(variant) + "</td><td>" + html::escape(name) + "</td><td>" +
             std::to_string(m.value("valid", 0)) + "</td><td>" + quantity(number(m, "mean"), unit) +
             "</td><td>" +
             html::escape(interval(m.value("ci95", Json()), unit, m.value("no_interval", "")) +
                          draw_list(m.value("draws", Json::array()))) +
             "</td><td>" + quantity(number(m, "median"), unit) + "</td></tr>\n";
    }
  return out + "</tbody></table>\n";
}

std::string pairs_section(const Json& doc) {
  std::string out =
      "<h2>Paired comparison (same draws)</h2>\n<p>Ratios only of quantities that are "
      "always positive: the electrical energy drawn from the supply and the RMS hand error "
      "(the geometric mean of A/B over the draws). The net electrical energy (drawn − "
      "regenerated) can be negative: its mean difference A − B. Each with its 95 % paired "
      "bootstrap interval.</p>\n<table id=\"mc-pairs\"><thead><tr>"
      "<th>A / B</th><th>metric</th><th>statistic</th><th>pairs</th><th>value</th>"
      "<th>95 % CI</th><th>A below B in</th><th>outcome</th></tr></thead><tbody>\n";
  for (const Json& p : doc["pairs"])
    for (const auto& [metric, r] : p.items()) {
      if (!r.is_object() || !r.contains("statistic")) continue;
      const bool ratio = r.value("statistic", "") == "ratio";
      const std::string unit = ratio ? "" : r.value("unit", "");
      const double value = number(r, ratio ? "ratio" : "difference");
      const std::string reason = r.value("reason", "");
      out += "<tr><td>" + html::escape(p.value("a", "") + " / " + p.value("b", "")) + "</td><td>" +
             html::escape(metric) + "</td><td>" + (ratio ? "ratio A/B" : "difference A − B") +
             "</td><td>" + std::to_string(r.value("pairs", 0)) + "</td><td>" +
             quantity(value, unit) + "</td><td>" +
             html::escape(interval(r.value("ci95", Json()), unit, "")) + "</td><td>" +
             html::escape(percent(number(r, "win_rate"))) + " of draws</td><td>" +
             html::escape(r.value("outcome", "") + (reason.empty() ? "" : ": " + reason) +
                          draw_list(r.value("draws", Json::array()))) +
             "</td></tr>\n";
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
      spread = "uniform in [" + significant(p["range"][0].get<double>()) + ", " +
               significant(p["range"][1].get<double>()) + "]";
    else
      spread = law + " ±" + significant(100 * p.value("spread", 0.0)) + " %" +
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
  add(ecdf(doc, metric::hand_error_rms, "RMS hand error over the draws",
           plot::log_axis("RMS hand error", "m")),
      "ecdf_hand_error.png",
      "Empirical distribution of each variant's RMS hand error (valid draws).");
  const EnergyShown energy = energy_shown(doc);
  add(ecdf(doc, energy.metric, "Electrical energy over the draws",
           plot::linear_axis(energy.label, "J")),
      "ecdf_energy.png",
      "Empirical distribution of each variant's " + energy.label + " (valid draws).");
  add(scatter(doc), "energy_vs_hand_error.png",
      "Each draw of each variant: " + energy.label + " against RMS hand error.");

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
                    "RMS hand error " + quantity(number(f, "hand_error_rms_step"), "m") +
                        " at step " + quantity(number(f, "step"), "s") + ", " +
                        quantity(number(f, "hand_error_rms_half_step"), "m") +
                        " at half of it: floor " + quantity(number(f, "floor"), "m")});
  page += html::info_table(rows);
  page += metrics_section(doc) + pairs_section(doc) + parameters_section(doc);
  page += "<h2>Distributions</h2>\n";
  for (const Figure& f : figures) page += html::figure(f);
  page += html::page_end();
  html::write_file(folder / "report.html", page);
  aside.keep();
}

}  // namespace elbowsim::report

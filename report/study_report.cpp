#include "report/study_report.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/recording/metrics.hpp"
#include "engine/recording/number_text.hpp"
#include "report/html.hpp"
#include "report/plot/plot.hpp"
#include "report/plots_aside.hpp"
#include "report/run_plots.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

// The quantities the study compares (app/study/paired_verdict.hpp kCompared),
// as the table heads them; a ratio is plotted, a difference is not.
struct Compared {
  const char* metric;
  const char* label;
  bool ratio;
  std::string unit() const { return elbowsim::metric_unit(metric); }  // the vocabulary's
};
constexpr Compared kCompared[] = {{metric::energy_drawn, "energy drawn", true},
                                  {metric::energy_in, "net energy", false},
                                  {metric::hand_error_rms, "RMS hand error", true}};

std::string fmt(const Json& x, const std::string& unit) {
  return x.is_number() ? quantity(x.get<double>(), unit) : "—";
}

std::string with_interval(const Json& value, const Json& ci, const std::string& unit) {
  std::string out = fmt(value, unit);
  if (ci.is_array() && ci.size() == 2)
    out += " (" + fmt(ci[0], unit) + (unit.empty() ? "–" : " to ") + fmt(ci[1], unit) + ")";
  return out;
}

// The pairs of variants the cases compare, as the first case lists them ("a", "b").
std::vector<std::pair<std::string, std::string>> pair_names(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> out;
  const Json& cases = doc["cases"];
  if (cases.empty()) return out;
  for (const Json& p : cases[0].value("pairs", Json::array()))
    out.emplace_back(p.value("a", ""), p.value("b", ""));
  return out;
}

// Pair `k`'s entry in a case (null when the case lacks it).
Json pair_of(const Json& c, std::size_t k) {
  const Json& pairs = c.value("pairs", Json::array());
  return k < pairs.size() ? pairs[k] : Json::object();
}

// The paired ratio of each ratio quantity per case for pair `k` ("a / b"),
// with its interval as a vertical bar; 1 is "no difference".
plot::LinePlot ratio_plot(const Json& doc, std::size_t k, const std::string& a, const std::string& b) {
  plot::LinePlot p;
  p.title = "Paired ratio per case, " + a + " / " + b + ", with 95 % intervals";
  p.x = plot::linear_axis("case (row of the table)", "");
  p.y = plot::log_axis("ratio " + a + " / " + b + " (geometric mean over draws)", "");
  p.width = 1100;
  const Json& cases = doc["cases"];
  int colour = 0;
  for (const Compared& m : kCompared) {
    if (!m.ratio) continue;
    plot::Series point, bars;
    point.label = m.label;
    point.color = bars.color = plot::palette(colour++);
    point.markers = true;
    for (std::size_t row = 0; row < cases.size(); ++row) {
      const Json pair = pair_of(cases[row], k);
      if (!pair.contains(m.metric)) continue;
      const Json& r = pair[m.metric];
      const double x = static_cast<double>(row + 1) + (colour == 1 ? -0.12 : 0.12);
      if (!r.value("ratio", Json()).is_number()) continue;
      point.x.insert(point.x.end(), {x, std::nan("")});
      point.y.insert(point.y.end(), {r["ratio"].get<double>(), std::nan("")});
      const Json ci = r.value("ci95", Json::array());
      if (ci.size() == 2 && ci[0].is_number() && ci[1].is_number()) {
        bars.x.insert(bars.x.end(), {x, x, std::nan("")});
        bars.y.insert(bars.y.end(), {ci[0].get<double>(), ci[1].get<double>(), std::nan("")});
      }
    }
    p.series.push_back(point);
    p.series.push_back(bars);
  }
  plot::Series one;
  one.label = "no difference (1)";
  one.color = plot::Color{0.4, 0.4, 0.4};
  one.dash = plot::Dash::dashed;
  one.x = {0.5, static_cast<double>(cases.size()) + 0.5};
  one.y = {1, 1};
  p.series.push_back(one);
  return p;
}

// The first pair's plot keeps the name it always had; the others are named by their pair.
std::string ratio_plot_file(std::size_t k, const std::string& a, const std::string& b) {
  return k == 0 ? "ratios.png" : "ratios_" + a + "_" + b + ".png";
}

std::string case_table(const Json& doc) {
  const Json& variants = doc.value("variants", Json::array());
  std::string out =
      "<h2>Cases</h2>\n<p>Means over the valid draws with their 95 % BCa bootstrap intervals "
      "(never below 0 for quantities that never are); energy drawn is what the supply "
      "delivered, net energy what it delivered less what the motors fed back (negative when "
      "they fed back more). Ratios (of energy drawn and of RMS hand error) and the difference of "
      "net energy are paired (same draw), a / b and a − b of each pair of variants; the "
      "outcome says whether the interval excludes 1 or 0 (and, for the hand error, whether the "
      "errors are above 10 × the accuracy floor); a case without a verdict gives the reason. "
      "Slips: the draws in which a variant's contacts began to slide after sticking, and the "
      "median slip events a run. "
      "No interval and no verdict below " +
      std::to_string(doc.value("min_interval_draws", 0)) +
      " draws where both runs are valid.</p>\n"
      "<table id=\"study-cases\"><thead><tr><th>#</th><th>case</th>";
  for (const Json& a : doc["axes"]) out += "<th>" + html::escape(a.value("name", "")) + "</th>";
  const auto pairs = pair_names(doc);
  for (const Compared& m : kCompared) {
    for (const Json& v : variants)
      out += "<th>" + std::string(m.label) + ", " + html::escape(v.get<std::string>()) + "</th>";
    for (const auto& [a, b] : pairs)
      out += std::string("<th>") + m.label + (m.ratio ? " ratio " : " difference ") +
             html::escape(a + (m.ratio ? " / " : " − ") + b) + "</th><th>" + m.label + ", " +
             html::escape(a + " against " + b) + "</th>";
  }
  for (const Json& v : variants)
    out += "<th>slips, " + html::escape(v.get<std::string>()) + "</th>";
  out += "<th>invalid runs</th></tr></thead><tbody>\n";
  int row = 0;
  for (const Json& c : doc["cases"]) {
    const std::string name = c.value("case", "");
    out += "<tr><td>" + std::to_string(++row) + "</td><td><a href=\"" + html::escape(name) +
           "/report.html\">" + html::escape(name) + "</a></td>";
    for (const Json& a : doc["axes"])
      out += "<td>" + html::escape(c["levels"].value(a.value("name", ""), "")) + "</td>";
    for (const Compared& m : kCompared) {
      for (const Json& v : variants) {
        const Json x = c.value("metrics", Json::object())
                           .value(v.get<std::string>(), Json::object())
                           .value(m.metric, Json::object());
        out += "<td class=\"num\">" +
               html::escape(
                   with_interval(x.value("mean", Json()), x.value("ci95", Json()), m.unit())) +
               "</td>";
      }
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        const Json r = pair_of(c, k).value(m.metric, Json::object());
        const std::string outcome = r.value("outcome", "no verdict");
        const std::string reason = r.value("reason", "");
        const Json value = r.value(m.ratio ? "ratio" : "difference", Json());
        out += "<td class=\"num\">" +
               html::escape(with_interval(value, r.value("ci95", Json()), m.ratio ? "" : m.unit())) +
               "</td><td class=\"outcome\" data-outcome=\"" + html::escape(outcome) + "\">" +
               html::escape(outcome + (reason.empty() ? "" : ": " + reason)) + "</td>";
      }
    }
    // Slip events: draws with any, and the median a run ("" from a study written before slips).
    for (const Json& v : variants) {
      const Json n = c.value("slips", Json::object()).value(v.get<std::string>(), Json::object());
      out += "<td class=\"num\">" +
             (n.empty() ? std::string()
                        : std::to_string(n.value("draws_with_slips", 0L)) + " draws, median " +
                              std::to_string(n.value("median", 0L))) +
             "</td>";
    }
    out += "<td class=\"num\">" + std::to_string(c.value("invalid_runs", 0)) + "</td></tr>\n";
  }
  return out + "</tbody></table>\n";
}

}  // namespace

void write_study_report(const std::filesystem::path& folder) {
  const Json doc = html::read_json(folder / "study.json");
  PlotsAside aside(folder);
  std::filesystem::create_directories(folder / "plots");
  const auto pairs = pair_names(doc);
  std::vector<std::pair<std::string, plot::LinePlot>> ratios;  // file, plot: one per pair
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto& [a, b] = pairs[k];
    ratios.emplace_back(ratio_plot_file(k, a, b), ratio_plot(doc, k, a, b));
    plot::write_png(ratios.back().second, folder / "plots" / ratios.back().first);
  }

  std::vector<std::string> verdict;
  for (const Json& line : doc.value("verdict", Json::array()))
    verdict.push_back(line.get<std::string>());
  const std::string name = doc.value("scenario", std::string());
  std::string page = html::page_begin("Study: " + name);
  page += "<h1>Monte Carlo study over " + std::to_string(doc["cases"].size()) +
          " cases: " + html::escape(name) + "</h1>\n";
  page += html::notice("verdict", "Verdict over the cases", verdict, "verdict");
  // Each axis's levels the cases ran (a --case selection runs some), and all of them where fewer.
  std::string axes;
  for (const Json& a : doc["axes"]) {
    const std::string axis = a.value("name", "");
    std::string all, ran;
    std::size_t all_count = 0, ran_count = 0;
    for (const Json& l : a["levels"]) {
      const std::string level = l.get<std::string>();
      all += (all.empty() ? "" : ", ") + level;
      ++all_count;
      bool used = false;
      for (const Json& c : doc["cases"]) used = used || c["levels"].value(axis, "") == level;
      if (!used) continue;
      ran += (ran.empty() ? "" : ", ") + level;
      ++ran_count;
    }
    axes += (axes.empty() ? "" : "; ") + axis + ": " + ran +
            (ran_count < all_count ? " (of " + all + ")" : "");
  }
  page += html::info_table({{"scenario file", doc.value("file", "")},
                            {"axes", axes},
                            {"draws per case", std::to_string(doc.value("samples", 0)) + " (seed " +
                                                   std::to_string(doc.value("seed", 0UL)) +
                                                   "), each applied to every variant"}});
  page += case_table(doc);
  if (!ratios.empty()) page += "<h2>Ratios per case</h2>\n";
  for (std::size_t k = 0; k < ratios.size(); ++k) {
    const auto& [a, b] = pairs[k];
    const plot::LinePlot& plot = ratios[k].second;
    page += html::figure({"plots/" + ratios[k].first, plot.title,
                          "Paired ratio " + a + " / " + b +
                              " per case (numbered as in the table): a point at the geometric "
                              "mean over the draws, a bar over its 95 % interval. Below 1: " +
                              a + " lower than " + b + ".",
                          plot.width, plot.height});
  }
  page += html::page_end();
  html::write_file(folder / "report.html", page);
  aside.keep();
}

}  // namespace elbowsim::report

#include "report/accuracy_report.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "engine/recording/number_text.hpp"
#include "report/html.hpp"
#include "report/plot/plot.hpp"
#include "report/plots_aside.hpp"

namespace elbowsim::report {

namespace {

using Json = nlohmann::ordered_json;

struct Measure {
  const char* key;
  const char* label;
  const char* unit;
  bool against_reference;  // in "errors" (vs the reference); else the run's own figure
};

constexpr Measure kMeasures[] = {
    {"hand_max", "maximum hand position error", "m", true},
    {"hand_rms", "RMS hand position error", "m", true},
    {"angle_final", "final joint angle error", "rad", true},
    {"angle_max", "maximum joint angle error", "rad", true},
    {"force_max", "maximum contact normal force error", "N", true},
    {"event_time", "landing/release time error", "s", true},
    {"balance_residual", "energy balance residual (the run's own)", "J", false},
    {"constraint_drift", "constraint drift max |C| (the run's own)", "m", false},
};

// A measure's value in a point, NaN when absent or null ("differ": infinity).
double value_of(const Json& point, const Measure& m) {
  const Json& where = m.against_reference ? point.value("errors", Json::object()) : point;
  if (!where.contains(m.key)) return std::nan("");
  const Json& v = where[m.key];
  if (v.is_string()) return std::numeric_limits<double>::infinity();
  return v.is_number() ? v.get<double>() : std::nan("");
}

// A measure as the tables show it: "—" where missing (NaN), "differ" where value_of says
// the runs' events differ (infinity), else `digits` significant digits.
std::string sci(double x, int digits = 3) {
  if (std::isnan(x)) return "—";
  if (std::isinf(x)) return "differ";
  return significant(x, digits);
}

std::string setting_text(const Json& p) {
  return p.value("method", "") + " " + p.value("setting", "") + " " + sci(p.value("value", 0.0));
}

std::string variant_name(const Json& study) {
  const std::string v = study.value("variant", "");
  return v.empty() ? "run" : v;
}

std::string file_stem(const Json& study, const Measure& m) {
  return "plots/" + variant_name(study) + "_wp_" + m.key + ".png";
}

plot::LinePlot measure_plot(const Json& study, const Measure& m) {
  std::vector<plot::MethodResult> methods;
  std::vector<plot::Series> intervals;  // each timing's 95 % interval, in its method's colour
  for (const Json& p : study["points"]) {
    const std::string method = p.value("method", "");
    if (methods.empty() || methods.back().method != method) methods.push_back({method, {}, {}});
    // A run that stopped early (diverged) has no error over the whole run; one
    // that completed but failed a validity check (its energy account, say)
    // still has a measured error, drawn like the others (the verdict skips it).
    if (!p.value("completed", false)) continue;
    methods.back().cpu_seconds.push_back(p.value("cpu_seconds", 0.0));
    methods.back().error.push_back(value_of(p, m));
    const Json ci = p.value("cpu_ci95", Json());
    if (!ci.is_array()) continue;
    plot::Series bar;
    bar.x = {ci[0].get<double>(), ci[1].get<double>()};
    bar.y = {value_of(p, m), value_of(p, m)};
    bar.color = plot::palette(static_cast<int>(methods.size()) - 1);
    bar.width = 1.2;
    intervals.push_back(bar);
  }
  plot::LinePlot plot = plot::work_precision_plot(
      methods, std::string(m.label) + " against CPU time — " + variant_name(study), m.label,
      m.unit);
  plot.series.insert(plot.series.end(), intervals.begin(), intervals.end());
  const Json& uncertainty = study["reference"].value("uncertainty", Json::object());
  if (m.against_reference && uncertainty.contains(m.key) && uncertainty[m.key].is_number() &&
      uncertainty[m.key].get<double>() > 0) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const auto& method : methods)
      for (double t : method.cpu_seconds) lo = std::min(lo, t), hi = std::max(hi, t);
    if (hi > 0) {
      plot::Series floor;
      floor.label = "reference uncertainty";
      floor.color = plot::Color{0.4, 0.4, 0.4};
      floor.dash = plot::Dash::dashed;
      floor.x = {lo, hi};
      floor.y = {uncertainty[m.key].get<double>(), uncertainty[m.key].get<double>()};
      plot.series.push_back(floor);
    }
  }
  return plot;
}

Json csv_cell_source(const Json& p, const char* key) {
  return p.contains(key) ? p[key] : Json(nullptr);
}

std::string cell(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return std::to_string(v.get<long>());
  return round_trip(v.get<double>());
}

std::string quoted(std::string text) {
  for (char& c : text)
    if (c == '"') c = '\'';
  return "\"" + text + "\"";
}

void csv_row(std::ostringstream& out, const std::string& variant, const std::string& kind,
             const std::string& method, const std::string& setting, const Json& value,
             const Json& p) {
  out << variant << "," << kind << "," << method << "," << setting << "," << cell(value) << ","
      << cell(p["completed"]) << "," << cell(p["valid"]);
  const Json ci = p.value("cpu_ci95", Json());
  out << "," << cell(csv_cell_source(p, "cpu_seconds")) << ","
      << (ci.is_array() ? cell(ci[0]) + "," + cell(ci[1]) : std::string(","));
  for (const char* key : {"repeats", "steps", "rejected_steps", "evaluations", "jacobians",
                          "factorisations", "stiff_from"})
    out << "," << cell(csv_cell_source(p, key));
  for (const Measure& m : kMeasures)
    out << ","
        << cell(m.against_reference ? csv_cell_source(p["errors"], m.key)
                                    : csv_cell_source(p, m.key));
  out << "," << quoted(p.value("failure", "")) << "\n";
}

// " (low–high, R timings)": the median CPU time's 95 % interval, where there is one.
std::string cpu_interval_text(const Json& p) {
  const Json ci = p.value("cpu_ci95", Json());
  const std::string count = std::to_string(p.value("repeats", 0)) + " timings";
  if (!ci.is_array()) return " (" + count + ")";
  return " (" + sci(ci[0].get<double>()) + "–" + sci(ci[1].get<double>()) + ", " + count + ")";
}

std::string points_table(const Json& study) {
  std::string out =
      "<table class=\"points\"><thead><tr><th>method</th><th>setting</th><th>valid</th>"
      "<th>CPU [s]</th><th>steps</th><th>rejected</th><th>evaluations</th>"
      "<th>hand max [m]</th><th>hand RMS [m]</th><th>final angle [rad]</th><th>force [N]</th>"
      "<th>event time [s]</th><th>balance [J]</th></tr></thead><tbody>\n";
  for (const Json& p : study["points"]) {
    out += "<tr><td>" + html::escape(p.value("method", "")) + "</td><td>" +
           html::escape(p.value("setting", "") + " " + sci(p.value("value", 0.0))) + "</td><td>" +
           (p.value("valid", false) ? "yes" : "<b>no</b>") + "</td><td>" +
           sci(p.value("cpu_seconds", 0.0)) + cpu_interval_text(p) + "</td><td>" +
           std::to_string(p.value("steps", 0L)) +
           "</td><td>" + std::to_string(p.value("rejected_steps", 0L)) +
           (p.value("stiff_from", Json()).is_number()
                ? ", stiff from " + sci(p["stiff_from"].get<double>()) + " s"
                : std::string()) +
           "</td><td>" +
           std::to_string(p.value("evaluations", 0L)) + "</td>";
    for (int k : {0, 1, 2, 4, 5, 6}) out += "<td>" + sci(value_of(p, kMeasures[k])) + "</td>";
    out += "</tr>\n";
  }
  return out + "</tbody></table>\n";
}

std::string alternatives_table(const Json& study) {
  if (study["alternatives"].empty()) return "";
  const Json& s = study["scene_setting"];
  std::string out = "<h3>Same setting, other algorithms</h3>\n<p>At the scene's own " +
                    html::escape(s.value("integrator", "")) +
                    " setting: the same equations "
                    "solved another way cost this much (errors against the same reference).</p>\n"
                    "<table class=\"alternatives\"><thead><tr><th>key</th><th>value</th>"
                    "<th>CPU [s]</th><th>valid</th><th>hand max [m]</th><th>event time [s]</th>"
                    "</tr></thead><tbody>\n";
  for (const Json& a : study["alternatives"])
    out += "<tr><td>" + html::escape(a.value("key", "")) + "</td><td>" +
           html::escape(a.value("value", "")) +
           (a.value("scene_default", false) ? " (scene)" : "") + "</td><td>" +
           sci(a.value("cpu_seconds", 0.0)) + "</td><td>" +
           (a.value("valid", false) ? "yes" : "<b>no</b>") + "</td><td>" +
           sci(value_of(a, kMeasures[0])) + "</td><td>" + sci(value_of(a, kMeasures[5])) +
           "</td></tr>\n";
  return out + "</tbody></table>\n";
}

// Tolerance proportionality of the adaptive methods: the largest joint-angle
// error each reached, divided by the rtol it was asked for, against that rtol
// (the angles are of order 1 rad, so rtol is an error in rad). A flat line:
// the error follows the tolerance; rising to the left: a floor (the
// reference, round-off) or a method that delivers less than it is asked.
plot::LinePlot proportionality_plot(const Json& study) {
  std::vector<plot::MethodResult> methods;
  for (const Json& p : study["points"]) {
    if (p.value("setting", "") != "rtol" || !p.value("completed", false)) continue;
    const std::string method = p.value("method", "");
    if (methods.empty() || methods.back().method != method) methods.push_back({method, {}, {}});
    const double rtol = p.value("value", 0.0);
    methods.back().cpu_seconds.push_back(rtol);
    methods.back().error.push_back(value_of(p, kMeasures[3]) / rtol);
  }
  plot::LinePlot plot = plot::work_precision_plot(
      methods, "Tolerance proportionality — " + variant_name(study),
      "maximum joint angle error / rtol", "rad");
  plot.x = plot::log_axis("requested rtol", "1");
  return plot;
}

// The settings whose runs are not in the verdict: stopped early (diverged,
// stalled, a bound broken) or completed but invalid, each with its reason.
std::string omissions_table(const Json& study) {
  std::string rows;
  const auto add = [&](const Json& p, const std::string& what) {
    if (p.value("valid", false)) return;
    rows += "<tr><td>" + html::escape(what) + "</td><td>" +
            (p.value("completed", false) ? "completed, invalid" : "stopped early") + "</td><td>" +
            html::escape(p.value("failure", "")) + "</td></tr>\n";
  };
  for (const Json& p : study["points"]) add(p, setting_text(p));
  for (const Json& a : study["alternatives"])
    add(a, a.value("key", "") + ": " + a.value("value", ""));
  if (rows.empty()) return "<h3>Omitted</h3>\n<p>None: every run is valid.</p>\n";
  return "<h3>Omitted</h3>\n<p>Runs the verdict does not choose, and why (the completed ones "
         "are still drawn above).</p>\n<table class=\"omissions\"><thead><tr><th>run</th>"
         "<th>outcome</th><th>reason</th></tr></thead><tbody>\n" +
         rows + "</tbody></table>\n";
}

}  // namespace

Json work_precision_verdict(const Json& doc, const std::vector<double>& targets) {
  Json out = Json::array();
  for (const Json& study : doc["studies"]) {
    const Json& uncertainty = study["reference"].value("uncertainty", Json::object());
    const double floor = value_of(Json{{"errors", uncertainty}}, kMeasures[0]);
    Json v;
    v["variant"] = study.value("variant", "");
    v["reference_uncertainty"] = std::isfinite(floor) ? Json(floor) : Json(nullptr);
    Json rows = Json::array();
    for (double target : targets) {
      Json row;
      row["target"] = target;
      if (!(std::isfinite(floor) && target >= floor)) {
        row["judged"] = false;
        row["text"] = "hand error " + sci(target) + " m: finer than the reference resolves (" +
                      sci(floor) + " m): not judged";
        rows.push_back(row);
        continue;
      }
      row["judged"] = true;
      const Json* best = nullptr;
      for (const Json& p : study["points"])
        if (p.value("valid", false) && value_of(p, kMeasures[0]) <= target &&
            (!best || p.value("cpu_seconds", 0.0) < (*best).value("cpu_seconds", 0.0)))
          best = &p;
      if (!best) {
        row["met"] = false;
        row["text"] = "hand error " + sci(target) + " m: no method and setting tried reaches it";
        rows.push_back(row);
        continue;
      }
      const Json* next = nullptr;
      for (const Json& p : study["points"])
        if (p.value("valid", false) && value_of(p, kMeasures[0]) <= target &&
            p.value("method", "") != (*best).value("method", "") &&
            (!next || p.value("cpu_seconds", 0.0) < (*next).value("cpu_seconds", 0.0)))
          next = &p;
      row["met"] = true;
      row["method"] = (*best)["method"];
      row["setting"] = (*best)["setting"];
      row["value"] = (*best)["value"];
      row["cpu_seconds"] = (*best)["cpu_seconds"];
      row["hand_max"] = (*best)["errors"]["hand_max"];
      std::string text = "hand error " + sci(target) + " m: cheapest " + setting_text(*best) +
                         " (" + sci((*best).value("cpu_seconds", 0.0)) + " s CPU, error " +
                         sci(value_of(*best, kMeasures[0])) + " m)";
      if (next) {
        const double ratio = (*next).value("cpu_seconds", 0.0) / (*best).value("cpu_seconds", 1.0);
        row["next"] = {{"method", (*next)["method"]},
                       {"setting", (*next)["setting"]},
                       {"value", (*next)["value"]},
                       {"cpu_seconds", (*next)["cpu_seconds"]}};
        row["ratio"] = ratio;
        text += "; next best " + setting_text(*next) + " costs " + sci(ratio, 2) + "x";
      } else {
        row["next"] = nullptr;
        text += "; no other method reaches it";
      }
      row["text"] = text;
      rows.push_back(row);
    }
    v["targets"] = rows;
    out.push_back(v);
  }
  return out;
}

std::string work_precision_csv(const Json& doc) {
  std::ostringstream out;
  out << "variant,kind,method,setting,value,completed,valid,cpu_seconds,cpu_low [s],cpu_high [s],"
         "repeats,steps,rejected_steps,"
         "evaluations,jacobians,factorisations,stiff_from [s]";
  for (const Measure& m : kMeasures) out << "," << m.key << " [" << m.unit << "]";
  out << ",failure\n";
  for (const Json& study : doc["studies"]) {
    const std::string variant = study.value("variant", "");
    for (const Json& p : study["points"])
      csv_row(out, variant, "sweep", p.value("method", ""), p.value("setting", ""), p["value"], p);
    const std::string scene = study["scene_setting"].value("integrator", "");
    for (const Json& a : study["alternatives"])
      csv_row(out, variant, "alternative", scene, a.value("key", ""), a["value"], a);
  }
  return out.str();
}

void write_accuracy_report(const Json& doc, const std::filesystem::path& folder) {
  PlotsAside aside(folder);
  std::filesystem::create_directories(folder / "plots");
  const std::string name = doc.value("scenario", "");
  std::string page = html::page_begin("Accuracy: " + name);
  page += "<h1>What accuracy costs in time: " + html::escape(name) + "</h1>\n";
  std::vector<std::string> verdict;
  for (const Json& v : doc.value("verdict", Json::array()))
    for (const Json& row : v["targets"])
      verdict.push_back((v.value("variant", "").empty() ? "" : v.value("variant", "") + ": ") +
                        row.value("text", ""));
  page += html::notice("verdict", "Cheapest setting per hand-error target (measured)", verdict,
                       "verdict");
  page +=
      "<p>Each point is one run of the scenario: CPU time of the integration (the controller's "
      "plan, the same for every run, left out; the median of its timings, with the median's "
      "95 % interval in the table from 6 timings on, timed again until that interval is within "
      "5 % of it) " +
      std::string(
          "against its error, compared row by row with "
          "a reference run. Invalid runs (diverged, penetrating, energy account off) "
          "are drawn when they completed (their error is measured) but never chosen by the "
          "verdict; runs that stopped early are left out. Fixed-step methods: "
          "steps step/m; adaptive methods: rtol 10<sup>-k</sup>, atol = rtol/1000.</p>\n");
  for (const Json& study : doc["studies"]) {
    const Json& ref = study["reference"];
    const Json& u = ref.value("uncertainty", Json::object());
    page += "<h2>" + html::escape(variant_name(study)) + "</h2>\n";
    page += html::info_table(
        {{"reference", "dopri5 rtol " + sci(ref.value("rtol", 0.0)) + ", " +
                           std::to_string(ref.value("steps", 0L)) + " steps, " +
                           sci(ref.value("cpu_seconds", 0.0)) + " s CPU, " +
                           std::to_string(ref.value("events", 0L)) + " contact events"},
         {"reference uncertainty (rtol " + sci(ref.value("rtol", 0.0)) + " vs " +
              sci(ref.value("check_rtol", 0.0)) + ")",
          "hand " + sci(value_of(Json{{"errors", u}}, kMeasures[0])) + " m, final angle " +
              sci(value_of(Json{{"errors", u}}, kMeasures[2])) + " rad, force " +
              sci(value_of(Json{{"errors", u}}, kMeasures[4])) + " N, event time " +
              sci(value_of(Json{{"errors", u}}, kMeasures[5])) + " s"},
         {"rows compared", std::to_string(u.value("rows", 0L)) + ", every " +
                               sci(study.value("record_interval", 0.0)) + " s"}});
    for (const Measure& m : kMeasures) {
      const plot::LinePlot p = measure_plot(study, m);
      bool any = false;
      for (const auto& s : p.series)
        for (double y : s.y) any = any || (std::isfinite(y) && y > 0);
      if (!any) continue;  // e.g. no contact: no force error
      const std::string file = file_stem(study, m);
      plot::write_png(p, folder / file);
      page +=
          html::figure({file, p.title,
                        std::string(m.label) + " [" + m.unit +
                            "] against CPU time [s], log-log, "
                            "one line per method (settings from coarse to fine), each point's "
                            "median CPU time with its 95 % interval as a bar" +
                            (m.against_reference ? "; dashed: what the reference resolves." : "."),
                        p.width, p.height});
    }
    const plot::LinePlot tolerance = proportionality_plot(study);
    if (!tolerance.series.empty()) {
      const std::string file = "plots/" + variant_name(study) + "_tolerance.png";
      plot::write_png(tolerance, folder / file);
      page += html::figure({file, tolerance.title,
                            "The adaptive methods' largest joint-angle error divided by the rtol "
                            "asked, against that rtol, log-log: flat where the error follows the "
                            "tolerance.",
                            tolerance.width, tolerance.height});
    }
    page += "<h3>Every point</h3>\n" + points_table(study) + alternatives_table(study) +
            omissions_table(study);
  }
  page += html::page_end();
  html::write_file(folder / "report.html", page);
  aside.keep();
}

}  // namespace elbowsim::report

#include "report/run_plots.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "report/columns.hpp"
#include "report/plot/plot.hpp"

namespace elbowsim::report {

namespace {

namespace fs = std::filesystem;
using plot::Axis;
using plot::Dash;
using plot::LinePlot;
using plot::Series;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A figure to draw, or the reason this run has none.
struct Planned {
  std::string name;  // file stem
  std::optional<LinePlot> plot;
  std::string caption;
  std::string skipped;  // why there is no plot (when plot is empty)
};

Planned skip(std::string name, std::string why) {
  return {std::move(name), {}, "", std::move(why)};
}

Series series(std::string label, std::vector<double> x, std::vector<double> y) {
  Series s;
  s.label = std::move(label);
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

std::string run_name(const RunData& run) {
  return run.has_summary() && run.summary.value("scenario", "") != ""
             ? run.summary["scenario"].get<std::string>()
             : run.label;
}

LinePlot time_plot(const RunData& run, const std::string& title, Axis y) {
  LinePlot p;
  p.title = title + " — " + run_name(run);
  p.y = std::move(y);
  return p;
}

// One line per column named prefix + j, against time.
Planned per_joint(const RunData& run, const std::string& name, const std::string& prefix,
                  const std::string& title, const std::string& quantity, const std::string& caption,
                  const std::string& why_missing) {
  const auto names = indexed_columns(run.trajectory, prefix);
  if (names.empty()) return skip(name, why_missing);
  LinePlot p =
      time_plot(run, title, plot::linear_axis(quantity, column_unit(run.trajectory, names[0])));
  const auto t = column(run.trajectory, "time");
  for (const std::string& c : names) p.series.push_back(series(c, t, column(run.trajectory, c)));
  return {name, std::move(p), caption, ""};
}

bool all_zero(const std::vector<double>& values) {
  for (double v : values)
    if (v != 0) return false;
  return true;
}

// hand_x, hand_z and hand_y, leaving out hand_y when it is 0 throughout (planar arms).
std::vector<std::string> hand_columns(const std::vector<const Recording*>& recordings) {
  bool planar = true;
  for (const Recording* rec : recordings) planar = planar && all_zero(column(*rec, "hand_y"));
  if (planar) return {"hand_x", "hand_z"};
  return {"hand_x", "hand_z", "hand_y"};
}

Planned hand_position(const RunData& run) {
  const Recording& rec = run.trajectory;
  if (rec.column("hand_x") < 0) return skip("hand_position", "no hand_x/y/z columns");
  LinePlot p = time_plot(run, "Hand position", plot::linear_axis("position", "m"));
  const auto t = column(rec, "time");
  const auto columns = hand_columns({&rec});
  bool desired = false;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const auto color = plot::palette(static_cast<int>(k));
    Series s = series(columns[k], t, column(rec, columns[k]));
    s.color = color;
    p.series.push_back(std::move(s));
    // The desired path (hand_d_x, ...) dashed in the same colour, when the task records one.
    const std::string wanted = "hand_d_" + columns[k].substr(5);
    if (rec.column(wanted) < 0) continue;
    Series d = series(wanted + " (desired)", t, column(rec, wanted));
    d.color = color;
    d.dash = Dash::dashed;
    d.width = 1.2;
    p.series.push_back(std::move(d));
    desired = true;
  }
  return {"hand_position", std::move(p),
          std::string("World coordinates of the hand point") +
              (desired ? "; dashed: the desired path" : "") +
              (columns.size() == 2 ? " (hand_y is 0 throughout, not drawn)." : "."),
          ""};
}

Planned hand_error(const RunData& run) {
  const auto e = column(run.trajectory, "hand_error");
  if (e.empty()) return skip("hand_error", "no hand_error column (no desired hand path)");
  LinePlot p = time_plot(run, "Hand error", plot::log_axis("|hand error|", "m"));
  std::vector<double> magnitude(e.size());
  for (std::size_t k = 0; k < e.size(); ++k) magnitude[k] = std::abs(e[k]);
  p.series.push_back(series("|hand_error|", column(run.trajectory, "time"), magnitude));
  p.empty_message = "no data: the hand error is 0 at every sample";
  return {"hand_error", std::move(p), "Distance from the hand to its desired path (log axis).", ""};
}

Planned power(const RunData& run) {
  const auto total = electrical_power(run.trajectory);
  if (total.empty()) return skip("electrical_power", "no motor columns (effects.motor: none)");
  LinePlot p = time_plot(run, "Electrical power", plot::linear_axis("power", "W"));
  const auto t = column(run.trajectory, "time");
  Series sum = series("Σ v·i", t, total);
  sum.width = 2.4;
  sum.color = plot::Color{0.15, 0.15, 0.15};
  p.series.push_back(std::move(sum));
  const auto volts = indexed_columns(run.trajectory, "v");
  for (std::size_t j = 0; j < volts.size(); ++j) {
    const auto v = column(run.trajectory, volts[j]);
    const auto i = column(run.trajectory, "i" + std::to_string(j));
    std::vector<double> pj(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) pj[k] = v[k] * i[k];
    Series s = series("v" + std::to_string(j) + "·i" + std::to_string(j), t, pj);
    s.width = 1.2;
    s.color = plot::palette(static_cast<int>(j));
    p.series.push_back(std::move(s));
  }
  return {"electrical_power", std::move(p),
          "Power into the motors, v·i per motor and summed, computed from the voltage and "
          "current columns.",
          ""};
}

Planned energy(const RunData& run) {
  const Recording& rec = run.trajectory;
  const auto e_in = column(rec, "E_in");
  if (e_in.empty()) return skip("energy", "no E_in column");
  LinePlot p = time_plot(run, "Cumulative energy", plot::linear_axis("energy", "J"));
  const auto t = column(rec, "time");
  p.series.push_back(series("E_in (electrical in)", t, e_in));
  if (rec.column("E_joule") >= 0)
    p.series.push_back(series("E_joule (Joule loss)", t, column(rec, "E_joule")));
  const auto power = electrical_power(rec);
  if (!power.empty()) {
    Series check = series("∫ Σ v·i dt (from samples)", t, running_integral(t, power));
    check.dash = Dash::dashed;
    check.color = plot::Color{0.2, 0.2, 0.2};
    check.width = 1.2;
    p.series.push_back(std::move(check));
  }
  return {"energy", std::move(p),
          "Electrical energy into the motors and the Joule loss in their windings, as the engine "
          "accounted them; dashed: the power samples integrated, a cross-check.",
          ""};
}

Planned contact_forces(const RunData& run) {
  const Recording& rec = run.trajectory;
  const auto elbows = elbow_names(rec);
  if (elbows.empty()) return skip("contact_forces", "no elbow columns (effects.contact off)");
  LinePlot p = time_plot(run, "Elbow normal forces", plot::linear_axis("normal force", "N"));
  p.y.include_zero = true;
  const auto t = column(rec, "time");
  for (std::size_t k = 0; k < elbows.size(); ++k) {
    const auto color = plot::palette(static_cast<int>(k));
    if (rec.column("fn_" + elbows[k]) >= 0) {
      Series s = series("fn_" + elbows[k], t, column(rec, "fn_" + elbows[k]));
      s.color = color;
      p.series.push_back(std::move(s));
    }
    if (rec.column("rest_" + elbows[k]) >= 0)
      p.lanes.push_back({elbows[k], intervals_on(t, column(rec, "rest_" + elbows[k])), color});
  }
  return {"contact_forces", std::move(p),
          "Normal force the table exerts on each elbow (f_n > 0 pushes); the strips below mark "
          "when each elbow rests.",
          ""};
}

Planned constraint_residual(const RunData& run) {
  const Recording& rec = run.trajectory;
  const auto elbows = elbow_names(rec);
  if (elbows.empty() || rec.column("d_" + elbows[0]) < 0)
    return skip("constraint_residual", "no d_<elbow> columns (effects.contact off)");
  LinePlot p = time_plot(run, "Constraint residual while resting", plot::log_axis("|d|", "m"));
  p.empty_message = "no data: no elbow rests with |d| > 0 (exactly on the table)";
  const auto t = column(rec, "time");
  for (const std::string& elbow : elbows) {
    auto d = column(rec, "d_" + elbow);
    const auto rest = column(rec, "rest_" + elbow);
    for (std::size_t k = 0; k < d.size(); ++k)
      d[k] = k < rest.size() && rest[k] >= 0.5 ? std::abs(d[k]) : kNaN;
    p.series.push_back(series("|d_" + elbow + "|", t, d));
  }
  return {"constraint_residual", std::move(p),
          "Distance of each resting elbow from the table surface, |C(q)|: the constraint drift "
          "left after stabilization (log axis; gaps where the elbow is lifted or |d| is 0).",
          ""};
}

Planned balance(const RunData& run) {
  auto r = column(run.trajectory, "balance_residual");
  if (r.empty()) return skip("energy_balance", "no balance_residual column");
  for (double& v : r) v = std::abs(v);
  LinePlot p = time_plot(run, "Energy-balance residual", plot::log_axis("|balance residual|", "J"));
  p.empty_message = "no data: the energy balance closes exactly (residual 0) at every sample";
  p.series.push_back(series("|balance_residual|", column(run.trajectory, "time"), r));
  return {"energy_balance", std::move(p),
          "What the energy account leaves unexplained: energy in minus stored minus dissipated "
          "(log axis). Small and smooth means the integration conserves energy as modelled.",
          ""};
}

std::vector<Planned> plan_run(const RunData& run) {
  return {
      per_joint(run, "joint_angles", "q", "Joint angles", "angle",
                "Joint angles q, relative to "
                "the previous link.",
                "no q columns"),
      hand_position(run),
      hand_error(run),
      per_joint(run, "motor_currents", "i", "Motor currents", "current", "Motor winding currents.",
                "no current columns (effects.motor: none)"),
      per_joint(run, "motor_voltages", "v", "Motor voltages", "voltage",
                "Voltages applied to the motors (after the voltage limit).",
                "no voltage columns (effects.motor: none)"),
      per_joint(run, "joint_torques", "tau", "Joint torques", "torque",
                "Torques the motors (or torque inputs) apply at the joints.", "no tau columns"),
      power(run),
      energy(run),
      contact_forces(run),
      constraint_residual(run),
      balance(run),
  };
}

// Draws what was planned; notes what was not.
FigureSet draw(std::vector<Planned> planned, const fs::path& folder) {
  fs::create_directories(folder / "plots");
  FigureSet set;
  for (Planned& p : planned) {
    if (!p.plot) {
      set.skipped.push_back(p.name + ": " + p.skipped);
      continue;
    }
    const std::string file = "plots/" + p.name + ".png";
    plot::write_png(*p.plot, folder / file);
    set.figures.push_back({file, p.plot->title, p.caption, p.plot->width, p.plot->height});
  }
  return set;
}

}  // namespace

FigureSet write_run_plots(const RunData& run, const fs::path& report_folder) {
  if (!run.has_trajectory()) {
    FigureSet set;
    set.skipped.push_back("all plots: no trajectory.csv samples in this run folder");
    return set;
  }
  return draw(plan_run(run), report_folder);
}

// ---- comparison -----------------------------------------------------------

namespace {

const Dash kDashes[] = {Dash::solid, Dash::dashed, Dash::dotted, Dash::dash_dot};

// One line per (run, column): colour by run, dash by column; |values| on a log axis.
Planned overlay(const std::vector<RunData>& runs, const std::string& name, const std::string& title,
                Axis y, const std::vector<std::string>& columns, const std::string& caption) {
  const bool magnitude = y.scale == plot::Scale::log;
  if (columns.empty()) return skip(name, "no run has these columns");
  LinePlot p;
  p.title = title;
  p.y = std::move(y);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto t = column(runs[r].trajectory, "time");
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (runs[r].trajectory.column(columns[c]) < 0) continue;
      auto values = column(runs[r].trajectory, columns[c]);
      if (magnitude)
        for (double& v : values) v = std::abs(v);
      Series s = series(runs[r].label + " " + columns[c], t, std::move(values));
      s.color = plot::palette(static_cast<int>(r));
      s.dash = kDashes[c % 4];
      p.series.push_back(std::move(s));
    }
  }
  if (p.series.empty()) return skip(name, "no run has " + columns[0]);
  return {name, std::move(p), caption, ""};
}

std::vector<std::string> all_indexed(const std::vector<RunData>& runs, const std::string& prefix) {
  std::vector<std::string> widest;
  for (const RunData& run : runs) {
    auto names = indexed_columns(run.trajectory, prefix);
    if (names.size() > widest.size()) widest = std::move(names);
  }
  return widest;
}

plot::BarChart totals(const std::vector<RunData>& runs) {
  plot::BarChart chart;
  chart.title = "Energy totals per run";
  chart.y = plot::linear_axis("energy", "J");
  chart.empty_message = "no data: no run has energy_final in summary.json";
  plot::BarGroup e_in{"electrical energy in (E_in)", {}}, joule{"Joule loss", {}};
  for (const RunData& run : runs) {
    chart.categories.push_back(run.label);
    const auto number = [&](const char* key) {
      const auto path = nlohmann::ordered_json::json_pointer(std::string("/energy_final/") + key);
      return run.has_summary() && run.summary.contains(path) && run.summary[path].is_number()
                 ? run.summary[path].get<double>()
                 : kNaN;
    };
    e_in.values.push_back(number("electrical_in"));
    joule.values.push_back(number("joule"));
  }
  chart.groups = {e_in, joule};
  return chart;
}

}  // namespace

FigureSet write_comparison_plots(const std::vector<RunData>& runs, const fs::path& report_folder) {
  std::vector<Planned> planned;
  planned.push_back(overlay(runs, "energy", "Cumulative energy", plot::linear_axis("energy", "J"),
                            {"E_in", "E_joule"},
                            "Electrical energy in (solid) and Joule loss (dashed), per run."));
  std::vector<const Recording*> recordings;
  for (const RunData& run : runs) recordings.push_back(&run.trajectory);
  const auto hand = hand_columns(recordings);
  planned.push_back(
      overlay(runs, "hand_position", "Hand position", plot::linear_axis("position", "m"), hand,
              hand.size() == 2 ? "Hand x (solid) and z (dashed), per run (y is 0 throughout)."
                               : "Hand x (solid), z (dashed) and y (dotted), per run."));
  planned.push_back(overlay(runs, "motor_currents", "Motor currents",
                            plot::linear_axis("current", "A"), all_indexed(runs, "i"),
                            "Winding currents; colour by run, dash by motor (i0 solid, i1 "
                            "dashed, i2 dotted, i3 dash-dot, then again)."));
  bool any_error = false;
  for (const RunData& run : runs) any_error = any_error || run.trajectory.column("hand_error") >= 0;
  if (any_error)
    planned.push_back(overlay(runs, "hand_error", "Hand error", plot::log_axis("|hand error|", "m"),
                              {"hand_error"},
                              "Distance from the hand to its desired path (log axis)."));
  FigureSet set = draw(std::move(planned), report_folder);
  const plot::BarChart bars = totals(runs);
  plot::write_png(bars, report_folder / "plots/totals.png");
  set.figures.push_back({"plots/totals.png", bars.title,
                         "Electrical energy in and Joule loss at the end of each run "
                         "(summary.json energy_final).",
                         bars.width, bars.height});
  return set;
}

}  // namespace elbowsim::report

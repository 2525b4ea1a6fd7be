#include "report/run_plots.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

#include "report/columns.hpp"
#include "report/headline.hpp"
#include "report/lead_figures.hpp"
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

LinePlot time_plot(const RunData& run, const std::string& title, Axis y) {
  LinePlot p;
  p.title = title + " — " + run_title(run);
  p.y = std::move(y);
  return p;
}

// A per-joint column of the layout: q, current, voltage, torque.
using JointColumn = int (TrajectoryLayout::*)(int) const;

// The per-joint columns of a run (empty when it did not record them).
std::vector<int> joint_columns(const Recording& rec, JointColumn which) {
  std::vector<int> out;
  for (int j = 0; j < rec.layout.dof(); ++j)
    if ((rec.layout.*which)(j) >= 0) out.push_back((rec.layout.*which)(j));
  return out;
}

// One line per joint's column, against time.
Planned per_joint(const RunData& run, const std::string& name, JointColumn which,
                  const std::string& title, const std::string& quantity, const std::string& caption,
                  const std::string& why_missing) {
  const Recording& rec = run.trajectory;
  const auto columns = joint_columns(rec, which);
  if (columns.empty()) return skip(name, why_missing);
  LinePlot p = time_plot(run, title, plot::linear_axis(quantity, column_unit(rec, columns[0])));
  const auto t = column(rec, rec.layout.time());
  for (int c : columns) p.series.push_back(series(column_name(rec, c), t, column(rec, c)));
  return {name, std::move(p), caption, ""};
}

bool all_zero(const std::vector<double>& values) {
  for (double v : values)
    if (v != 0) return false;
  return true;
}

// The hand axes to draw: x, z and y, leaving out y when it is 0 throughout (planar arms).
std::vector<int> hand_axes(const std::vector<const Recording*>& recordings) {
  bool planar = true;
  for (const Recording* rec : recordings)
    planar = planar && all_zero(column(*rec, rec->layout.hand(1)));
  if (planar) return {0, 2};
  return {0, 2, 1};
}

Planned hand_position(const RunData& run) {
  const Recording& rec = run.trajectory;
  LinePlot p = time_plot(run, "Hand position", plot::linear_axis("position", "m"));
  const auto t = column(rec, rec.layout.time());
  const auto axes = hand_axes({&rec});
  bool desired = false;
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const auto color = plot::palette(static_cast<int>(k));
    const int hand = rec.layout.hand(axes[k]);
    Series s = series(column_name(rec, hand), t, column(rec, hand));
    s.color = color;
    p.series.push_back(std::move(s));
    // The desired path (hand_d_x, ...) dashed in the same colour, when the task records one.
    const int wanted = rec.layout.hand_desired(axes[k]);
    if (wanted < 0) continue;
    Series d = series(column_name(rec, wanted) + " (desired)", t, column(rec, wanted));
    d.color = color;
    d.dash = Dash::dashed;
    d.width = 1.2;
    p.series.push_back(std::move(d));
    desired = true;
  }
  return {"hand_position", std::move(p),
          std::string("World coordinates of the hand point") +
              (desired ? "; dashed: the desired path" : "") +
              (axes.size() == 2 ? " (hand_y is 0 throughout, not drawn)." : "."),
          ""};
}

Planned hand_error(const RunData& run) {
  const Recording& rec = run.trajectory;
  const auto e = column(rec, rec.layout.hand_error());
  if (e.empty()) return skip("hand_error", "no hand_error column (no desired hand path)");
  LinePlot p = time_plot(run, "Hand error", plot::log_axis("|hand error|", "m"));
  std::vector<double> magnitude(e.size());
  for (std::size_t k = 0; k < e.size(); ++k) magnitude[k] = std::abs(e[k]);
  p.series.push_back(series("|hand_error|", column(rec, rec.layout.time()), magnitude));
  p.empty_message = "no data: the hand error is 0 at every sample";
  return {"hand_error", std::move(p), "Distance from the hand to its desired path (log axis).", ""};
}

Planned power(const RunData& run) {
  const auto total = electrical_power(run.trajectory);
  if (total.empty()) return skip("electrical_power", "no motor columns (effects.motor: none)");
  LinePlot p = time_plot(run, "Electrical power", plot::linear_axis("power", "W"));
  const Recording& rec = run.trajectory;
  const auto t = column(rec, rec.layout.time());
  Series sum = series("Σ v·i", t, total);
  sum.width = 2.4;
  sum.color = plot::Color{0.15, 0.15, 0.15};
  p.series.push_back(std::move(sum));
  for (int j = 0; j < rec.layout.dof(); ++j) {
    const auto v = column(rec, rec.layout.voltage(j));
    const auto i = column(rec, rec.layout.current(j));
    std::vector<double> pj(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) pj[k] = v[k] * i[k];
    Series s = series("v" + std::to_string(j) + "·i" + std::to_string(j), t, pj);
    s.width = 1.2;
    s.color = plot::palette(j);
    p.series.push_back(std::move(s));
  }
  return {"electrical_power", std::move(p),
          "Power into the motors, v·i per motor and summed, computed from the voltage and "
          "current columns.",
          ""};
}

Planned energy(const RunData& run) {
  const Recording& rec = run.trajectory;
  const auto e_in = column(rec, rec.layout.energy(Energy::electrical_in));
  LinePlot p = time_plot(run, "Cumulative energy", plot::linear_axis("energy", "J"));
  const auto t = column(rec, rec.layout.time());
  p.series.push_back(series("E_in (electrical in, net)", t, e_in));
  p.series.push_back(series("E_joule (Joule loss)", t, column(rec, rec.layout.energy(Energy::joule))));
  const auto drawn = column(rec, rec.layout.energy(Energy::drawn));
  if (!drawn.empty()) {
    p.series.push_back(series("E_drawn", t, drawn));
    p.series.push_back(
        series("E_regenerated", t, column(rec, rec.layout.energy(Energy::regenerated))));
  }
  // Potential energy given up since t = 0: the other source of the Joule loss.
  auto given_up = column(rec, rec.layout.energy(Energy::potential));
  for (std::size_t k = given_up.size(); k-- > 0;) given_up[k] = given_up[0] - given_up[k];
  p.series.push_back(series("PE given up (PE(0) − PE)", t, given_up));
  const auto power = electrical_power(rec);
  if (!power.empty()) {
    Series check = series("∫ Σ v·i dt (from samples)", t, running_integral(t, power));
    check.dash = Dash::dashed;
    check.color = plot::Color{0.2, 0.2, 0.2};
    check.width = 1.2;
    p.series.push_back(std::move(check));
  }
  return {
      "energy", std::move(p),
      "Electrical energy into the motors (net, and split into drawn and regenerated), the Joule "
      "loss in their windings and the potential energy the arm gave up, as the engine "
      "accounted them over time; dashed: the power samples integrated, a cross-check of E_in.",
      ""};
}

Planned contact_forces(const RunData& run) {
  const Recording& rec = run.trajectory;
  const TrajectoryLayout& L = rec.layout;
  if (L.elbows() == 0) return skip("contact_forces", "no elbow columns (effects.contact off)");
  LinePlot p = time_plot(run, "Elbow normal forces", plot::linear_axis("normal force", "N"));
  p.y.include_zero = true;
  const auto t = column(rec, L.time());
  for (int k = 0; k < L.elbows(); ++k) {
    const auto color = plot::palette(k);
    Series s = series(column_name(rec, L.elbow_force(k)), t, column(rec, L.elbow_force(k)));
    s.color = color;
    p.series.push_back(std::move(s));
    p.lanes.push_back({L.groups().elbows[k], intervals_on(t, column(rec, L.elbow_resting(k))), color});
  }
  return {"contact_forces", std::move(p),
          "Normal force the table exerts on each elbow (f_n > 0 pushes); the strips below mark "
          "when each elbow rests.",
          ""};
}

Planned constraint_residual(const RunData& run) {
  const Recording& rec = run.trajectory;
  const TrajectoryLayout& L = rec.layout;
  if (L.elbows() == 0)
    return skip("constraint_residual", "no d_<elbow> columns (effects.contact off)");
  LinePlot p = time_plot(run, "Constraint residual while resting", plot::log_axis("|d|", "m"));
  p.empty_message = "no data: no elbow rests with |d| > 0 (exactly on the table)";
  const auto t = column(rec, L.time());
  for (int e = 0; e < L.elbows(); ++e) {
    auto d = column(rec, L.elbow_distance(e));
    const auto rest = column(rec, L.elbow_resting(e));
    for (std::size_t k = 0; k < d.size(); ++k) d[k] = rest[k] >= 0.5 ? std::abs(d[k]) : kNaN;
    p.series.push_back(series("|" + column_name(rec, L.elbow_distance(e)) + "|", t, d));
  }
  return {"constraint_residual", std::move(p),
          "Distance of each resting elbow from the table surface, |C(q)|: the constraint drift "
          "left after stabilization (log axis; gaps where the elbow is lifted or |d| is 0).",
          ""};
}

Planned balance(const RunData& run) {
  const Recording& rec = run.trajectory;
  auto r = column(rec, rec.layout.balance_residual());
  for (double& v : r) v = std::abs(v);
  LinePlot p = time_plot(run, "Energy-balance residual", plot::log_axis("|balance residual|", "J"));
  p.empty_message = "no data: the energy balance closes exactly (residual 0) at every sample";
  p.series.push_back(series("|balance_residual|", column(rec, rec.layout.time()), r));
  return {"energy_balance", std::move(p),
          "What the energy account leaves unexplained: energy in minus stored minus dissipated "
          "(log axis). Small and smooth means the integration conserves energy as modelled.",
          ""};
}

std::vector<Planned> plan_run(const RunData& run) {
  return {
      per_joint(run, "joint_angles", &TrajectoryLayout::q, "Joint angles", "angle",
                "Joint angles q, relative to "
                "the previous link.",
                "no q columns"),
      hand_position(run),
      hand_error(run),
      per_joint(run, "motor_currents", &TrajectoryLayout::current, "Motor currents", "current",
                "Motor winding currents.",
                "no current columns (effects.motor: none)"),
      per_joint(run, "motor_voltages", &TrajectoryLayout::voltage, "Motor voltages", "voltage",
                "Voltages applied to the motors (after the voltage limit).",
                "no voltage columns (effects.motor: none)"),
      per_joint(run, "joint_torques", &TrajectoryLayout::torque, "Joint torques", "torque",
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
  FigureSet set;
  add_lead_figures(run, report_folder, set);
  if (!run.has_trajectory()) {
    set.skipped.push_back("time plots: no trajectory.csv samples in this run folder");
    return set;
  }
  FigureSet rest = draw(plan_run(run), report_folder);
  set.figures.insert(set.figures.end(), rest.figures.begin(), rest.figures.end());
  set.skipped.insert(set.skipped.end(), rest.skipped.begin(), rest.skipped.end());
  return set;
}

// ---- comparison -----------------------------------------------------------

namespace {

const Dash kDashes[] = {Dash::solid, Dash::dashed, Dash::dotted, Dash::dash_dot};

// A column chosen in each run's own layout (runs may differ in layout).
using ColumnOf = std::function<int(const TrajectoryLayout&)>;

// One line per (run, column): colour by run, dash by column; |values| on a log axis.
Planned overlay(const std::vector<RunData>& runs, const std::string& name, const std::string& title,
                Axis y, const std::vector<ColumnOf>& columns, const std::string& caption) {
  const bool magnitude = y.scale == plot::Scale::log;
  if (columns.empty()) return skip(name, "no run has these columns");
  LinePlot p;
  p.title = title + " — " + comparison_title(runs);
  p.y = std::move(y);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Recording& rec = runs[r].trajectory;
    const auto t = column(rec, rec.layout.time());
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const int index = rec.layout.size() > 0 ? columns[c](rec.layout) : -1;
      if (index < 0) continue;
      auto values = column(rec, index);
      if (magnitude)
        for (double& v : values) v = std::abs(v);
      Series s = series(runs[r].label + " " + column_name(rec, index), t, std::move(values));
      s.color = plot::palette(static_cast<int>(r));
      s.dash = kDashes[c % 4];
      p.series.push_back(std::move(s));
    }
  }
  if (p.series.empty()) return skip(name, "no run has these columns");
  return {name, std::move(p), caption, ""};
}

// The motor currents of the widest arm among the runs.
std::vector<ColumnOf> all_currents(const std::vector<RunData>& runs) {
  int widest = 0;
  for (const RunData& run : runs)
    if (run.trajectory.layout.has_motors()) widest = std::max(widest, run.trajectory.layout.dof());
  std::vector<ColumnOf> out;
  for (int j = 0; j < widest; ++j)
    out.push_back([j](const TrajectoryLayout& L) { return j < L.dof() ? L.current(j) : -1; });
  return out;
}

}  // namespace

FigureSet write_comparison_plots(const std::vector<RunData>& runs, const fs::path& report_folder) {
  FigureSet set;
  add_comparison_lead_figures(runs, report_folder, set);
  std::vector<Planned> planned;
  planned.push_back(overlay(runs, "energy", "Cumulative energy", plot::linear_axis("energy", "J"),
                            {[](const TrajectoryLayout& L) { return L.energy(Energy::electrical_in); },
                             [](const TrajectoryLayout& L) { return L.energy(Energy::joule); }},
                            "Electrical energy in (solid) and Joule loss (dashed), per run."));
  std::vector<const Recording*> recordings;
  for (const RunData& run : runs)
    if (run.has_trajectory()) recordings.push_back(&run.trajectory);
  std::vector<ColumnOf> hand;
  for (int axis : hand_axes(recordings))
    hand.push_back([axis](const TrajectoryLayout& L) { return L.hand(axis); });
  planned.push_back(
      overlay(runs, "hand_position", "Hand position", plot::linear_axis("position", "m"), hand,
              hand.size() == 2 ? "Hand x (solid) and z (dashed), per run (y is 0 throughout)."
                               : "Hand x (solid), z (dashed) and y (dotted), per run."));
  planned.push_back(overlay(runs, "motor_currents", "Motor currents",
                            plot::linear_axis("current", "A"), all_currents(runs),
                            "Winding currents; colour by run, dash by motor (i0 solid, i1 "
                            "dashed, i2 dotted, i3 dash-dot, then again)."));
  bool any_error = false;
  for (const RunData& run : runs)
    any_error = any_error || run.trajectory.layout.has_desired_hand();
  if (any_error)
    planned.push_back(overlay(runs, "hand_error", "Hand error", plot::log_axis("|hand error|", "m"),
                              {[](const TrajectoryLayout& L) { return L.hand_error(); }},
                              "Distance from the hand to its desired path (log axis)."));
  FigureSet rest = draw(std::move(planned), report_folder);
  set.figures.insert(set.figures.end(), rest.figures.begin(), rest.figures.end());
  set.skipped.insert(set.skipped.end(), rest.skipped.begin(), rest.skipped.end());
  return set;
}

}  // namespace elbowsim::report

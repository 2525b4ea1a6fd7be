#include "engine/run/warnings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/recording/number_text.hpp"
#include "engine/run/fixed_step_stability.hpp"

namespace elbowsim {

namespace {

// Seconds each recorded row stands for: from its time to the next row's
// (the last row stands for nothing), and their sum.
std::vector<double> row_spans(const Recording& recording) {
  const std::size_t rows = recording.rows();
  std::vector<double> spans(rows, 0.0);
  const int t = recording.layout.time();
  for (std::size_t r = 0; r + 1 < rows; ++r) spans[r] = recording.at(r + 1, t) - recording.at(r, t);
  return spans;
}

// Lengths in warnings: um below 1 mm, mm below 1 m, else m (ASCII, as the warnings are).
constexpr Unit kLengthUnits[] = {{"m", 1}, {"mm", 1e3}, {"um", 1e6}};

}  // namespace

std::vector<double> saturation_shares(const Model& model, const Recording& recording) {
  const TrajectoryLayout& L = recording.layout;
  if (!model.has_motor() || !L.has_motors() || L.dof() != model.dof) return {};
  const std::vector<double> spans = row_spans(recording);
  double total = 0;
  for (double s : spans) total += s;
  std::vector<double> shares(static_cast<std::size_t>(model.dof), 0.0);
  if (!(total > 0)) return shares;
  // At a limit to a relative 1e-9: motor.cpp clamps to the limit exactly, a
  // commanded voltage inside it differs by far more than rounding.
  constexpr double kAt = 1 - 1e-9;
  for (int j = 0; j < model.dof; ++j) {
    const double v_max = model.voltage_limit[j], i_max = model.current_limit[j];
    double held = 0;
    for (std::size_t r = 0; r < spans.size(); ++r) {
      const double v = recording.at(r, L.voltage(j));
      bool limited = std::abs(v) >= kAt * v_max;
      if (i_max < std::numeric_limits<double>::infinity()) {
        const double drop = v - model.km[j] * recording.at(r, L.qd(j));
        limited = limited || std::abs(drop) >= kAt * model.resistance[j] * i_max;
      }
      if (limited) held += spans[r];
    }
    shares[static_cast<std::size_t>(j)] = held / total;
  }
  return shares;
}

namespace {

// "motor 1 is at its voltage limit (24 V) for 30 % of the run".
std::string saturation_clause(const Model& model, int j, double share) {
  const bool current = model.current_limit[j] < std::numeric_limits<double>::infinity();
  char limit[96];
  std::snprintf(
      limit, sizeof limit,
      current ? "voltage limit (%.3g V) or current limit (%.3g A)" : "voltage limit (%.3g V)",
      model.voltage_limit[j], model.current_limit[j]);
  return "motor " + std::to_string(j) + " is at its " + limit + " for " +
         percent(share, PercentDigits::three) + " of the run";
}

}  // namespace

std::vector<std::string> saturation_warnings(const Model& model,
                                             const std::vector<double>& shares) {
  std::vector<std::string> out;
  for (std::size_t j = 0; j < shares.size(); ++j) {
    if (!(shares[j] > model.warn.saturation_share)) continue;
    out.push_back(saturation_clause(model, int(j), shares[j]) + " (warnings: saturation_share " +
                  percent(model.warn.saturation_share, PercentDigits::three) +
                  "): it cannot give what it is asked, so the arm follows the limit, not the "
                  "command; a larger gear ratio, torque constant or voltage, or a slower task, "
                  "would let it");
  }
  return out;
}

std::vector<std::string> lift_off_warnings(const Model& model, const ContactGeometry& geometry,
                                           const std::vector<ContactEvent>& events,
                                           const std::vector<int>& planned_resting) {
  std::vector<std::string> out;
  for (int k : planned_resting) {
    int count = 0;
    double first = 0;
    for (const ContactEvent& e : events) {
      if (e.kind != ContactEvent::Kind::release || e.slot < 0 ||
          e.slot >= static_cast<int>(geometry.slots.size()))
        continue;
      const int primitive = geometry.slots[static_cast<std::size_t>(e.slot)].primitive;
      if (geometry.primitives[static_cast<std::size_t>(primitive)].elbow != k) continue;
      if (count++ == 0) first = e.t;
    }
    if (count == 0) continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  "elbow '%s', which the task keeps on the table, lifted off at t = %.4g s%s: the "
                  "plan assumed it resting (its force and the hand's path are not what was "
                  "planned while it is up)",
                  model.elbows[static_cast<std::size_t>(k)].name.c_str(), first,
                  count > 1 ? (" (" + std::to_string(count) + " times in all)").c_str() : "");
    out.emplace_back(text);
  }
  return out;
}

namespace {

// A link's own solid, or an elbow the task holds above the table.
bool unplanned(const Metrics& metrics, std::size_t b, const std::vector<int>& held) {
  return metrics.body_links[b] >= 0 || std::find(held.begin(), held.end(), int(b)) != held.end();
}

}  // namespace

UnplannedContact longest_unplanned_contact(const Metrics& metrics, const std::vector<int>& held) {
  UnplannedContact out;
  const Metric* share = metrics.find(metric::body_rest_fraction);
  if (!share) return out;
  for (std::size_t b = 0; b < metrics.bodies.size(); ++b)
    if (unplanned(metrics, b, held) && share->values[b] > out.share)
      out = {share->values[b], metrics.bodies[b]};
  return out;
}

std::vector<std::string> unplanned_contact_warnings(const Model& model, const Metrics& metrics,
                                                    const std::vector<int>& held) {
  const Metric* share = metrics.find(metric::body_rest_fraction);
  const Metric* mean = metrics.find(metric::body_force_mean);
  const Metric* peak = metrics.find(metric::body_force_peak);
  if (!share || !mean || !peak) return {};
  std::vector<std::string> out;
  for (std::size_t b = 0; b < metrics.bodies.size(); ++b) {
    const int link = metrics.body_links[b];
    const bool held_elbow = link < 0 && unplanned(metrics, b, held);
    if (!unplanned(metrics, b, held) || !(share->values[b] > model.warn.unplanned_contact_share))
      continue;
    const std::string what =
        held_elbow ? "elbow '" + metrics.bodies[b] + "', which the task holds above the table,"
                   : metrics.bodies[b] + " (link " + std::to_string(link) +
                         "'s own solid, not a declared elbow)";
    char forces[96];
    std::snprintf(forces, sizeof forces, "mean %.3g N while resting, peak %.3g N", mean->values[b],
                  peak->values[b]);
    out.push_back(what + " rested on the table for " +
                  percent(share->values[b], PercentDigits::three) + " of the run (" + forces +
                  "; warnings: unplanned_contact_share " +
                  percent(model.warn.unplanned_contact_share, PercentDigits::three) +
                  "): the table carried part of the arm there, so the run's energy and accuracy "
                  "are those of an arm leaning on it; declare it as an elbow, or raise the arm "
                  "or the table");
  }
  return out;
}

std::vector<std::string> hand_error_warnings(const Model& model, const Recording& recording) {
  const int column = recording.layout.hand_error();
  if (column < 0 || recording.rows() == 0) return {};
  std::size_t worst = 0;
  for (std::size_t r = 1; r < recording.rows(); ++r)
    if (recording.at(r, column) > recording.at(worst, column)) worst = r;
  const double largest = recording.at(worst, column);
  if (!(largest > model.warn.hand_error)) return {};
  const std::string when = significant(recording.at(worst, recording.layout.time()), 4) + " s";
  return {"the hand was " + in_units(largest, kLengthUnits) + " from its desired point at t = " +
          when + ", above warnings: hand_error (" + in_units(model.warn.hand_error, kLengthUnits) +
          "): the arm did not do the task it was given"};
}

std::vector<std::string> motor_rating_warnings(const Model& model, const Metrics& metrics) {
  std::vector<std::string> out;
  const Metric* rms = metrics.find(metric::current_rms);
  if (!model.has_motor() || !rms) return out;
  for (int j = 0; j < model.dof; ++j) {
    const double rated = model.motors[static_cast<std::size_t>(j)].rated_current;
    const double i = rms->values[static_cast<std::size_t>(j)];
    if (!(i > rated)) continue;
    const bool builtin = model.motors[static_cast<std::size_t>(j)].builtin;
    char text[400];
    std::snprintf(text, sizeof text,
                  "motor %d carries %.3g A RMS, %.2g times its rated continuous current %.3g A "
                  "(motors: rated_current%s): a real motor of this rating would overheat",
                  j, i, i / rated, rated,
                  builtin ? "; the built-in motor, a 20 W class servo behind 100:1: give the arm "
                            "motors of its size under motors:"
                          : "");
    out.emplace_back(text);
  }
  return out;
}

namespace {

// The model's fixed step on the system linearised at initial.q, or nothing
// (adaptive integrators, an unfinalized model, more than kStabilityMaxJoints joints).
bool fixed_step_at_start(const Model& model, const ControllerSpec* controller,
                         FixedStepStability& out) {
  if (is_adaptive(model.options.integrator) || model.dof == 0 ||
      model.dof > kStabilityMaxJoints || model.km.size() != model.dof ||
      model.viscous.size() != model.dof)
    return false;
  const Eigen::VectorXd q =
      model.initial.q.size() == model.dof ? model.initial.q : Eigen::VectorXd::Zero(model.dof);
  out = fixed_step_stability(model, model.options.integrator, controller, q);
  return true;
}

// "the rk4 integrator is unstable at the step 0.001 s on ... (...)": the
// clause both the warning and the failure cause start with.
std::string instability(const Model& model, const FixedStepStability& s) {
  char text[360];
  std::snprintf(text, sizeof text,
                "the %s integrator is unstable at the step %.3g s on the motor-arm system "
                "linearised at initial.q: one step amplifies errors %.3g times (stable up to a "
                "step of about %.3g s; engine/MODEL.md, Stability of the fixed steps)",
                to_string(model.options.integrator), model.options.step, s.radius, s.stable_step);
  return text;
}

}  // namespace

std::vector<std::string> stiffness_warnings(const Model& model, const ControllerSpec* controller) {
  FixedStepStability s;
  if (!fixed_step_at_start(model, controller, s)) return {};
  const double h = model.options.step;
  const bool unresolved = s.fastest >= 0 && s.electrical_time < 0.1 * h;
  char text[800];
  if (s.radius > kStableRadius) {
    char electrics[200] = "";
    if (unresolved)
      std::snprintf(electrics, sizeof electrics,
                    "; motor %d's electrical time constant L/R = %.3g s is under a tenth of the "
                    "step, where a stable fixed step is still only first-order accurate",
                    s.fastest, s.electrical_time);
    std::snprintf(text, sizeof text,
                  "%s%s: use simulation.integrator: ros34pw2 (implicit, stable at any step; "
                  "without simulation.integrator, auto chooses it here) or simulation.step <= "
                  "%.3g s",
                  instability(model, s).c_str(), electrics, s.stable_step);
    return {text};
  }
  if (!unresolved) return {};
  std::snprintf(text, sizeof text,
                "motor %d's electrical time constant L/R = %.3g s is under a tenth of the step "
                "%.3g s: the %s integrator is stable there on the motor-arm system linearised at "
                "initial.q (one step's spectral radius %.3g), but its currents and angles are "
                "only first-order accurate (engine/MODEL.md, Integration); for accurate currents "
                "use simulation.integrator: ros34pw2 (what auto chooses here) or motor: "
                "quasi_static",
                s.fastest, s.electrical_time, h, to_string(model.options.integrator), s.radius);
  return {text};
}

std::vector<FailureCause> stiffness_causes(const Model& model, const ControllerSpec* controller) {
  FixedStepStability s;
  if (!fixed_step_at_start(model, controller, s) || !(s.radius > kStableRadius)) return {};
  using K = Failure::Kind;
  return {{instability(model, s),
           0.0,
           {K::diverged, K::current_bound, K::speed_bound, K::energy_balance, K::penetration}}};
}

std::vector<FailureCause> saturation_causes(const Model& model, const std::vector<double>& shares) {
  std::vector<FailureCause> out;
  for (std::size_t j = 0; j < shares.size(); ++j)
    if (shares[j] > model.warn.saturation_share)
      out.push_back({saturation_clause(model, int(j), shares[j]) +
                         " (it cannot give what it is asked: the arm follows the limit)",
                     0.0,
                     {Failure::Kind::elbow_not_resting}});
  return out;
}

std::vector<std::string> first_link_elbow_warnings(const Model& model) {
  std::vector<std::string> out;
  if (!model.effects.contact) return out;
  for (const Elbow& e : model.elbows) {
    if (e.link != 0) continue;
    std::string text =
        "elbow '" + e.name +
        "' is on link 0, whose points move with joint 0 alone: while it rests on the "
        "table joint 0 is held still (the arm moves with joints 1 and up)";
    if (model.effects.friction)
      text +=
          "; its normal and friction rows of M* are then dependent (rank 1), so only the "
          "force's moment about joint 0 is determined and the minimum-norm split between "
          "normal and friction force is used";
    out.push_back(std::move(text));
  }
  return out;
}

std::vector<std::string> model_warnings(const Model& model, const ControllerSpec* controller) {
  std::vector<std::string> out = stiffness_warnings(model, controller);
  for (std::string& w : first_link_elbow_warnings(model)) out.push_back(std::move(w));
  return out;
}

}  // namespace elbowsim

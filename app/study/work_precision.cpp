#include "app/study/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/simulator.hpp"
#include "engine/step_grid.hpp"
#include "report/statistics.hpp"

namespace elbowsim::study {

namespace {

using Json = nlohmann::ordered_json;

constexpr double kReferenceRtol = 1e-11, kCheckRtol = 1e-10;
// Fixed steps step / m: integer m keeps every row at the same time.
constexpr int kStepDivisors[] = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64};

// A JSON number, or null for NaN and infinity (JSON has neither).
Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

struct Timed {
  RunResult result;
  double cpu_seconds = 0;  // median, the plan left out
  report::Interval cpu_interval;  // the median's 95 % interval, when has_interval
  bool has_interval = false;
  double plan_cpu_seconds = 0;
  int repeats = 0;
};

// Runs `model` at least `repeats` times and keeps the median CPU time (the
// results are identical: same binary, same input). From kMinTimedForInterval
// repeats on, more follow until the median's 95 % interval lies within
// kTimingPrecision of it, at most kMaxRepeats or kTimingBudget of CPU; a run
// over 2 s is timed once.
Timed timed_run(const Model& model, const Experiment& experiment, int every, int repeats,
                const std::atomic<bool>* stop) {
  Timed out;
  std::vector<double> times;
  const auto settled = [&] {
    if (repeats < kMinTimedForInterval) return static_cast<int>(times.size()) >= repeats;
    if (static_cast<int>(times.size()) < repeats) return false;
    double spent = 0;
    for (double t : times) spent += t;
    if (static_cast<int>(times.size()) >= kMaxRepeats || spent >= kTimingBudget) return true;
    report::Interval ci;
    if (!report::median_interval(times, 0.95, ci)) return false;
    const double m = report::median(times);
    return ci.high - m <= kTimingPrecision * m && m - ci.low <= kTimingPrecision * m;
  };
  while (!settled()) {
    // The integration's time: the plan (the same for every run of a study)
    // is computed inside simulate() and left out.
    const double start = thread_cpu_seconds();
    RunResult result = simulate(model, experiment, RunOptions{every, {}, stop});
    times.push_back(thread_cpu_seconds() - start - result.plan_cpu_seconds);
    out.plan_cpu_seconds = result.plan_cpu_seconds;
    if (times.size() == 1) out.result = std::move(result);
    if (times.front() > 2.0 || out.result.interrupted) break;
  }
  out.cpu_seconds = report::median(times);
  out.has_interval = report::median_interval(times, 0.95, out.cpu_interval);
  out.repeats = static_cast<int>(times.size());
  return out;
}

Json errors_json(const RunErrors& e) {
  return {{"angle_final", number(e.angle_final)}, {"angle_max", number(e.angle_max)},
          {"hand_max", number(e.hand_max)},       {"hand_rms", number(e.hand_rms)},
          {"force_max", number(e.force_max)},     {"event_time", std::isinf(e.event_time) ? Json("differ") : number(e.event_time)},
          {"rows", e.rows}};
}

Json point_json(const Timed& t, const RunResult& reference) {
  const RunResult& r = t.result;
  Json j;
  j["completed"] = r.completed;  // reached the end: its errors are measured (valid or not)
  j["valid"] = r.valid;
  j["failure"] = r.failure;
  j["cpu_seconds"] = t.cpu_seconds;
  j["plan_cpu_seconds"] = t.plan_cpu_seconds;  // not in cpu_seconds: every run follows the same plan
  j["repeats"] = t.repeats;
  // The median's distribution-free 95 % interval (from 6 timings on).
  j["cpu_ci95"] = t.has_interval ? Json::array({t.cpu_interval.low, t.cpu_interval.high}) : Json();
  j["steps"] = r.steps;
  j["rejected_steps"] = r.work.rejected;
  j["evaluations"] = r.work.evaluations;
  j["jacobians"] = r.work.jacobians;
  j["factorisations"] = r.work.factorisations;
  // dopri5's stiffness test (engine/run/adaptive.hpp): stability, not the tolerance, set its steps.
  j["stiff_from"] = r.stiff_from >= 0 ? Json(r.stiff_from) : Json();
  try {
    j["errors"] = errors_json(compare_runs(r, reference));
  } catch (const std::invalid_argument& e) {  // not comparable: no error, never chosen
    j["completed"] = j["valid"] = false;
    j["failure"] = std::string("not compared with the reference: ") + e.what();
    j["errors"] = Json::object();
  }
  j["balance_residual"] = number(r.max_abs_balance_residual);  // [J] the run's own account
  j["constraint_drift"] = number(r.contact.max_abs_C);        // [m]
  return j;
}

Model with_setting(Model m, IntegratorKind kind, double value, int& every, int scene_every) {
  m.options.integrator = kind;
  every = scene_every;
  if (is_adaptive(kind)) {
    m.options.rtol = value;
    m.options.atol = 1e-3 * value;
  } else {
    const int divisor = static_cast<int>(std::lround(m.options.step / value));
    m.options.step = value;
    every = scene_every * divisor;
  }
  return m;
}

// Events as (slot, kind, time) in order.
double event_error(const RunResult& run, const RunResult& reference) {
  if (reference.events.empty() && run.events.empty()) return std::nan("");
  if (reference.events.size() != run.events.size()) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (std::size_t k = 0; k < run.events.size(); ++k) {
    const ContactEvent &a = run.events[k], &b = reference.events[k];
    if (a.slot != b.slot || a.kind != b.kind) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(a.t - b.t));
  }
  return worst;
}

}  // namespace

std::vector<double> method_settings(IntegratorKind kind, double step, int points) {
  std::vector<double> out;
  const int n = std::clamp(points, 2, static_cast<int>(std::size(kStepDivisors)));
  for (int k = 0; k < n; ++k) {
    if (kind == IntegratorKind::dopri5)
      out.push_back(1e-3 * std::pow(10.0, -k));
    else if (kind == IntegratorKind::ros34pw2)  // order 3: tight tolerances are not its ground
      out.push_back(1e-2 * std::pow(10.0, -k));
    else
      out.push_back(step / kStepDivisors[k]);
  }
  return out;
}

RunErrors compare_runs(const RunResult& run, const RunResult& reference) {
  const Recording &a = run.trajectory, &b = reference.trajectory;
  RunErrors e;
  const std::size_t rows = std::min(a.rows(), b.rows());
  e.rows = static_cast<long>(rows);
  std::vector<std::pair<int, int>> angles;  // (run, reference) column of each joint angle
  for (int j = 0; a.column('q' + std::to_string(j)) >= 0; ++j)
    angles.push_back({a.column('q' + std::to_string(j)), b.column('q' + std::to_string(j))});
  std::vector<std::pair<int, int>> forces;
  for (std::size_t c = 0; c < a.columns().size(); ++c) {
    const std::string& name = a.columns()[c].name;
    if (name.rfind("fn_", 0) == 0) forces.push_back({static_cast<int>(c), b.column(name)});
  }
  const int hand_a = a.column("hand_x"), hand_b = b.column("hand_x");
  double hand_sq = 0;
  e.force_max = forces.empty() ? std::nan("") : 0.0;
  for (std::size_t row = 0; row < rows; ++row) {
    const bool same_time = step_grid::same_recorded_time(a.at(row, 0), b.at(row, 0));
    // A run that stopped early ends on a row at its stopping time: compare up to it.
    if (!same_time && row + 1 == rows && (!run.completed || !reference.completed)) {
      e.rows = static_cast<long>(row);
      break;
    }
    if (!same_time)
      throw std::invalid_argument("rows at different times: " + std::to_string(a.at(row, 0)) +
                                  " s vs " + std::to_string(b.at(row, 0)) + " s (row " +
                                  std::to_string(row) + ")");
    double angle = 0;
    for (const auto& [ca, cb] : angles) angle = std::max(angle, std::abs(a.at(row, ca) - b.at(row, cb)));
    e.angle_max = std::max(e.angle_max, angle);
    e.angle_final = angle;  // the last row compared
    double hand = 0;
    for (int k = 0; k < 3; ++k) hand += std::pow(a.at(row, hand_a + k) - b.at(row, hand_b + k), 2);
    e.hand_max = std::max(e.hand_max, std::sqrt(hand));
    hand_sq += hand;
    for (const auto& [ca, cb] : forces)
      if (cb >= 0) e.force_max = std::max(e.force_max, std::abs(a.at(row, ca) - b.at(row, cb)));
  }
  e.hand_rms = e.rows ? std::sqrt(hand_sq / static_cast<double>(e.rows)) : std::nan("");
  e.event_time = event_error(run, reference);
  return e;
}

Json work_precision(const Scenario& scenario, const WorkPrecisionOptions& options) {
  const Model& scene = scenario.model;
  // Every run follows the same plan, sampled as the scene's: the study changes
  // the integration only (task.plan_step).
  Experiment pinned = scenario.experiment;
  if (pinned.task.plan_step <= 0) pinned.task.plan_step = scene.options.step;
  const Experiment& experiment = pinned;
  const int every = scenario.output.every;
  auto stopped = [&] { return options.stop && options.stop->load(); };
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };

  // The reference and its check.
  auto reference_model = [&](double rtol) {
    Model m = scene;
    m.options.integrator = IntegratorKind::dopri5;
    m.options.rtol = rtol;
    m.options.atol = 1e-3 * rtol;
    return m;
  };
  const Timed reference = timed_run(reference_model(kReferenceRtol), experiment, every, 1, options.stop);
  if (stopped()) return Json();
  if (!reference.result.valid)
    throw ReferenceInvalid("the reference run (dopri5, rtol 1e-11) is not valid: " +
                           reference.result.failure);
  say("reference: dopri5 rtol 1e-11, " + std::to_string(reference.result.steps) + " steps, " +
      significant(reference.cpu_seconds, 3) + " s CPU");
  const Timed check = timed_run(reference_model(kCheckRtol), experiment, every, 1, options.stop);
  if (stopped()) return Json();
  if (!check.result.valid) say("the reference's check (rtol 1e-10) is not valid: " + check.result.failure);
  Json doc;
  doc["scenario"] = scenario.file;
  doc["variant"] = scenario.variant;
  doc["record_interval"] = every * scene.options.step;
  doc["scene_setting"] = {{"integrator", to_string(scene.options.integrator)},
                          {"step", scene.options.step},
                          {"rtol", scene.options.rtol}};
  Json ref;
  ref["method"] = "dopri5";
  ref["rtol"] = kReferenceRtol;
  ref["atol"] = 1e-3 * kReferenceRtol;
  ref["check_rtol"] = kCheckRtol;
  ref["valid"] = reference.result.valid;
  ref["check_valid"] = check.result.valid;
  if (!check.result.valid) ref["check_failure"] = check.result.failure;
  ref["steps"] = reference.result.steps;
  ref["cpu_seconds"] = reference.cpu_seconds;
  ref["plan_cpu_seconds"] = reference.plan_cpu_seconds;
  ref["events"] = reference.result.events.size();
  // The two tolerances' difference bounds the reference's own error (the
  // tighter run is ~10x better still when the error is proportional to rtol).
  const RunErrors uncertainty = compare_runs(check.result, reference.result);
  ref["uncertainty"] = errors_json(uncertainty);
  doc["reference"] = ref;
  say("reference check: rtol 1e-10 differs from 1e-11 by " + significant(uncertainty.hand_max, 3) +
      " m in the hand, " + significant(uncertainty.angle_max, 3) +
      " rad in the angles: errors below that are not resolved");

  std::vector<IntegratorKind> methods = options.methods;
  if (methods.empty())
    methods = {IntegratorKind::euler, IntegratorKind::semi_implicit_euler, IntegratorKind::rk4,
               IntegratorKind::dopri5, IntegratorKind::ros34pw2};
  Json points = Json::array();
  for (IntegratorKind kind : methods)
    for (double value : method_settings(kind, scene.options.step, options.points)) {
      if (stopped()) break;
      int run_every = every;
      const Model m = with_setting(scene, kind, value, run_every, every);
      const Timed t = timed_run(m, experiment, run_every, options.repeats, options.stop);
      if (stopped()) return Json();
      Json p;
      p["method"] = to_string(kind);
      p["setting"] = is_adaptive(kind) ? "rtol" : "step";
      p["value"] = value;
      p.update(point_json(t, reference.result));
      const Json& hand = p["errors"]["hand_max"];
      say(std::string(to_string(kind)) + (is_adaptive(kind) ? " rtol " : " step ") +
          significant(value, 3) + ": " + significant(t.cpu_seconds, 3) + " s CPU, hand error " +
          (hand.is_number() ? significant(hand.get<double>(), 3) : std::string("-")) + " m" +
          (t.result.valid ? "" : " (NOT VALID: " + t.result.failure.substr(0, 80) + ")"));
      points.push_back(p);
    }
  doc["points"] = points;

  // Equal accuracy, different cost: at the scene's own integrator and setting.
  Json alternatives = Json::array();
  auto alternative = [&](const std::string& key, const std::string& value, Model m) {
    if (stopped()) return;
    const Timed t = timed_run(m, experiment, every, options.repeats, options.stop);
    if (stopped()) return;
    Json a;
    a["key"] = key;
    a["value"] = value;
    a["scene_default"] = false;
    a.update(point_json(t, reference.result));
    say(key + "=" + value + ": " + significant(t.cpu_seconds, 3) + " s CPU");
    alternatives.push_back(a);
  };
  if (options.alternatives) {
    for (DynamicsMethod d : {DynamicsMethod::walker_orin, DynamicsMethod::crba, DynamicsMethod::aba}) {
      Model m = scene;
      m.options.dynamics = d;
      alternative("simulation.dynamics", to_string(d), m);
    }
    if (scene.effects.contact) {
      for (ConstraintSolver s : {ConstraintSolver::schur, ConstraintSolver::aba,
                                 ConstraintSolver::dense_lu, ConstraintSolver::explicit_inverse}) {
        Model m = scene;
        m.contact.solver = s;
        alternative("contact.solver", to_string(s), m);
      }
      for (EventTiming e : {EventTiming::step, EventTiming::locate}) {
        Model m = scene;
        m.contact.events = e;
        alternative("contact.events", to_string(e), m);
      }
    }
    for (Json& a : alternatives) {
      const std::string key = a["key"], value = a["value"];
      a["scene_default"] = (key == "simulation.dynamics" && value == to_string(scene.options.dynamics)) ||
                           (key == "contact.solver" && value == to_string(constraint_solver(scene))) ||
                           (key == "contact.events" && value == to_string(scene.contact.events));
    }
  }
  if (stopped()) return Json();
  doc["alternatives"] = alternatives;
  return doc;
}

}  // namespace elbowsim::study

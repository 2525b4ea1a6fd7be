// task, controller and hand_load: the paper's experiment. The hand task (a
// path with a time scaling, the elbows the inverse kinematics keeps on the
// table, its posture and joint limits), the controller that tracks it, and a
// constant load at the hand. Keys are documented in scenarios/README.md.
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

using Path = HandTask::Path;
using Kind = ControllerSpec::Kind;

const char* path_name(Path p) {
  switch (p) {
    case Path::none:
      return "none";
    case Path::hold:
      return "hold";
    case Path::line:
      return "line";
    case Path::circle:
      return "circle";
    case Path::waypoints:
      return "waypoints";
  }
  return "?";
}

// A point of task.points: [x, y, z], or the word `start` (first point only),
// stored as NaN: the engine replaces a non-finite first point with the hand's
// position at the initial pose.
Eigen::Vector3d read_point(const Value& v, bool first) {
  if (v.present() && !v.is_sequence() && !v.is_map() && v.text() == "start") {
    if (!first) v.fail("only the first point may be `start` (the hand at the initial pose)");
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  return v.vec3();
}

// points: line exactly 2, waypoints at least 2, hold exactly 1 (default:
// [start]). Not allowed for a circle.
std::vector<Eigen::Vector3d> read_points(const Value& task, Path path) {
  std::vector<Eigen::Vector3d> out;
  const Value points = task.get("points");
  if (path == Path::hold && !points.present()) return out;  // hold the start
  if (path == Path::circle) return out;
  const std::vector<Value> items = task.require("points").items();
  for (std::size_t k = 0; k < items.size(); ++k) out.push_back(read_point(items[k], k == 0));
  const std::size_t n = out.size();
  const std::string got = " (got " + std::to_string(n) + ")";
  if (path == Path::line && n != 2) points.fail("a line needs exactly 2 points" + got);
  if (path == Path::hold && n != 1) points.fail("hold needs exactly 1 point" + got);
  if (path == Path::waypoints && n < 2) points.fail("waypoints need at least 2 points" + got);
  return out;
}

// Keys that belong to one kind of path only are errors on the others.
void check_path_keys(const Value& task, Path path) {
  const bool circle = path == Path::circle;
  for (const char* key : {"center", "radius", "normal", "start_angle"}) {
    if (!circle && task.get(key).exists())
      task.get(key).fail(std::string("is only for path: circle (this path is ") + path_name(path) +
                         ")");
  }
  if (circle && task.get("points").present())
    task.get("points").fail("is not used by path: circle (give center, radius, normal)");
}

void read_circle(const Value& task, HandTask& out) {
  out.center = task.require("center").vec3();
  out.radius = positive(task.require("radius"));
  const Value normal = task.get("normal");
  if (normal.present()) {
    const Eigen::Vector3d n = normal.vec3();
    if (!(n.norm() > 1e-12)) normal.fail("must be non-zero");
    out.normal = n.normalized();
  }
  out.start_angle = value_or(task.get("start_angle"), out.start_angle, number);
}

// elbows: names from the elbows: section, each once.
std::vector<std::string> read_task_elbows(const Value& elbows, const Model& model) {
  std::vector<std::string> out;
  if (!elbows.present()) return out;
  std::set<std::string> seen;
  for (const Value& v : elbows.items()) {
    const std::string name = v.text();
    bool known = false;
    std::vector<std::string_view> names;
    for (const Elbow& e : model.elbows) {
      known = known || e.name == name;
      names.push_back(e.name);
    }
    if (!known)
      v.fail("no elbow named \"" + name + "\" in elbows: " +
             (names.empty() ? std::string("(the scenario has none)") : join(names)));
    if (!seen.insert(name).second) v.fail("elbow \"" + name + "\" is listed twice");
    out.push_back(name);
  }
  // The inverse kinematics places these elbows relative to the table top.
  if (!out.empty() && model.table.empty())
    elbows.fail("needs a table: the table section is missing (give table: {boxes: [...]})");
  return out;
}

// joint_limits: {min: [..], max: [..]}, one per joint each, min < max.
void read_joint_limits(const Value& limits, int dof, HandTask& out) {
  if (!limits.present()) return;
  limits.allow_keys({"min", "max"});
  const Value min = limits.require("min"), max = limits.require("max");
  out.q_min = per_joint(min, dof);
  out.q_max = per_joint(max, dof);
  const std::vector<Value> max_items = max.items();
  for (int j = 0; j < dof; ++j) {
    if (!(out.q_min[j] < out.q_max[j]))
      max_items[static_cast<std::size_t>(j)].fail("must be > min[" + std::to_string(j) + "] (min " +
                                                  significant(out.q_min[j]) + ", max " +
                                                  significant(out.q_max[j]) + ")");
  }
}

// kp / kd: one number for every joint, or one per joint; each >= 0.
Eigen::VectorXd read_gains(const Value& v, double fallback, int dof) {
  if (!v.present()) return Eigen::VectorXd::Constant(dof, fallback);
  if (!v.is_sequence()) return Eigen::VectorXd::Constant(dof, non_negative(v));
  const Eigen::VectorXd out = per_joint(v, dof);
  const std::vector<Value> items = v.items();
  for (const Value& item : items) non_negative(item);
  return out;
}

// controller.tuning: {bandwidth: Hz, damping: zeta, integral: alpha}
// (engine/control/tuning.hpp).
TuningRule read_tuning(const Value& tuning) {
  TuningRule out;
  tuning.allow_keys({"bandwidth", "damping", "integral"});
  out.bandwidth = positive(tuning.require("bandwidth"));
  out.damping = value_or(tuning.get("damping"), out.damping, positive);
  out.integral = value_or(tuning.get("integral"), out.integral, non_negative);
  return out;
}

}  // namespace

HandTask read_task(const Value& task, const Model& model) {
  HandTask out;
  if (!task.present()) return out;
  task.allow_keys({"path", "timing", "start_delay", "duration", "points", "center", "radius",
                   "normal", "start_angle", "origin", "elbows", "elbow_clearance",
                   "posture", "posture_weight", "joint_limits", "plan_step"});
  out.path = choose(task.require("path"),
                    std::vector<std::pair<Path, std::string_view>>{{Path::hold, "hold"},
                                                                   {Path::line, "line"},
                                                                   {Path::circle, "circle"},
                                                                   {Path::waypoints, "waypoints"}});
  const Value timing = task.get("timing");
  if (timing.present())
    out.timing = choose(timing, std::vector<std::pair<HandTask::Timing, std::string_view>>{
                                    {HandTask::Timing::quintic, "quintic"},
                                    {HandTask::Timing::minimum_jerk, "minimum_jerk"}});
  out.start_delay = value_or(task.get("start_delay"), out.start_delay, non_negative);
  out.duration = value_or(task.get("duration"), out.duration, positive);
  const Value origin = task.get("origin");
  if (origin.present())
    out.from_start =
        choose(origin, std::vector<std::pair<bool, std::string_view>>{{false, "world"}, {true, "start"}});
  check_path_keys(task, out.path);
  out.points = read_points(task, out.path);
  if (out.path == Path::circle) read_circle(task, out);
  out.elbows = read_task_elbows(task.get("elbows"), model);
  out.elbow_clearance = value_or(task.get("elbow_clearance"), out.elbow_clearance, non_negative);
  const int dof = model.dof;
  out.posture = value_or(task.get("posture"), model.initial.q,
                         [dof](const Value& v) { return per_joint(v, dof); });
  out.posture_weight = value_or(task.get("posture_weight"), out.posture_weight, positive);
  out.plan_step = value_or(task.get("plan_step"), out.plan_step, positive);
  read_joint_limits(task.get("joint_limits"), dof, out);
  return out;
}

ControllerSpec read_controller(const Value& controller, const Model& model, const HandTask& task) {
  ControllerSpec out;
  const int dof = model.dof;
  constexpr double kDefaultKp = 50.0, kDefaultKd = 2.0;  // [V/rad], [V s/rad]
  out.kp = Eigen::VectorXd::Constant(dof, kDefaultKp);
  out.kd = Eigen::VectorXd::Constant(dof, kDefaultKd);
  if (!controller.present()) return out;
  controller.allow_keys({"type", "kp", "kd", "ki", "tuning", "desired_force", "model",
                         "sample_rate", "delay", "pwm_bits", "sensors"});
  const Value type = controller.get("type");
  if (type.present())
    out.kind = choose(type, std::vector<std::pair<Kind, std::string_view>>{
                                {Kind::open_loop, "open_loop"},
                                {Kind::pd, "pd"},
                                {Kind::pd_feedforward, "pd_feedforward"},
                                {Kind::force, "force"}});
  out.kp = read_gains(controller.get("kp"), kDefaultKp, dof);
  out.kd = read_gains(controller.get("kd"), kDefaultKd, dof);
  out.ki = read_gains(controller.get("ki"), 0.0, dof);
  const Value tuning = controller.get("tuning");
  if (tuning.present()) {
    for (const char* key : {"kp", "kd", "ki"})
      if (controller.get(key).present())
        tuning.fail(std::string("places kp, kd and ki by its rule: give the rule or the gains "
                                "(controller.") + key + "), not both");
    out.tuning = read_tuning(tuning);
  }
  out.desired_force = value_or(controller.get("desired_force"), out.desired_force, positive);
  out.loop = read_digital_loop(controller, model.options.step);
  if (out.kind == Kind::open_loop) {
    if (tuning.present())
      tuning.fail("an open-loop scene has no gains to tune (give controller.type pd, "
                  "pd_feedforward or force)");
    if (out.loop.sampled())
      controller.get("sample_rate").fail("an open-loop scene has no control loop to sample (give "
                                         "controller.type pd, pd_feedforward or force)");
    return out;
  }
  // Integral action is the sampled loop's state: continuous control has none.
  const bool integral = out.integral() || out.tuning.integral > 0;
  if (integral && !out.loop.sampled()) {
    const Value where = out.integral() ? controller.get("ki") : tuning.get("integral");
    where.fail("integral action runs in the digital loop: needs controller.sample_rate");
  }
  // A closed-loop controller tracks the task through the motors.
  const std::string kind = type.text();
  if (task.path == Path::none)
    type.fail("controller " + kind +
              " needs a task: the task section is missing (give task: "
              "{path: ..., ...})");
  if (!model.has_motor())
    type.fail("controller " + kind +
              " drives motor voltages: needs effects.motor quasi_static "
              "or full (got none)");
  if (out.kind != Kind::force) return out;
  if (task.elbows.empty())
    type.fail(
        "force control commands the elbow force: needs task.elbows (the elbows kept on "
        "the table)");
  if (!model.effects.contact)
    type.fail("force control commands the elbow force: needs effects.contact: true");
  return out;
}

HandLoad read_hand_load(const Value& hand_load) {
  HandLoad out;
  if (!hand_load.present()) return out;
  hand_load.allow_keys({"mass", "force"});
  out.mass = value_or(hand_load.get("mass"), out.mass, non_negative);
  out.force = value_or(hand_load.get("force"), out.force, vec3);
  return out;
}

}  // namespace elbowsim::loader

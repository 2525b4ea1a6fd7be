// effects, simulation, initial and output: the run settings around the robot.
#include <cmath>
#include <limits>
#include <numbers>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

// initial.<key> [rad or rad/s] or initial.<key>_deg [deg or deg/s], not both.
Eigen::VectorXd read_angles(const Value& initial, const std::string& key, int dof) {
  Value radians = initial.get(key);
  Value degrees = initial.get(key + "_deg");
  if (radians.exists() && degrees.exists())
    degrees.fail("give either " + key + " or " + key + "_deg, not both");
  if (degrees.present()) return per_joint(degrees, dof) * (std::numbers::pi / 180.0);
  return value_or(radians, Eigen::VectorXd::Zero(dof).eval(),
                  [dof](const Value& v) { return per_joint(v, dof); });
}

// rtol, atol and max_step steer the adaptive integrators only: with a fixed
// step they would be silently ignored, so they are refused there (with auto,
// once it has chosen: check_error_control).
void read_error_control(const Value& simulation, Options& out) {
  if (!auto_integrator(simulation)) check_error_control(simulation, out);
  out.rtol = value_or(simulation.get("rtol"), out.rtol, positive);
  out.atol = value_or(simulation.get("atol"), out.atol, positive);
  out.max_step = value_or(simulation.get("max_step"), out.max_step, positive);
  if (out.rtol < 1e-14)
    simulation.get("rtol").fail("must be >= 1e-14 (below it rounding decides every step)");
}

}  // namespace

bool auto_integrator(const Value& simulation) {
  if (!simulation.present()) return true;
  const Value integrator = simulation.get("integrator");
  return !integrator.present() || integrator.text() == "auto";
}

void check_error_control(const Value& simulation, const Options& options) {
  if (!simulation.present()) return;
  for (const char* key : {"rtol", "atol", "max_step"}) {
    Value v = simulation.get(key);
    if (!v.present() || is_adaptive(options.integrator)) continue;
    const std::string chosen = (options.integrator_reason.empty() ? "" : "simulation.integrator auto chose ") +
                               std::string(to_string(options.integrator)) +
                               (options.integrator_reason.empty() ? "" : ", which");
    v.fail(std::string("applies to the adaptive integrators only (dopri5, ros34pw2); ") + chosen +
           " takes a fixed simulation.step (to drop the key: --set simulation." + key +
           "=null; or name an adaptive integrator)");
  }
}

Effects read_effects(const Value& effects) {
  Effects out;
  if (!effects.present()) return out;
  effects.allow_keys({"gravity", "damping", "motor", "rotor_inertia", "contact", "friction",
                      "impacts", "stabilization", "joint_friction"});
  out.gravity = value_or(effects.get("gravity"), out.gravity, boolean);
  out.damping = value_or(effects.get("damping"), out.damping, boolean);
  out.rotor_inertia = value_or(effects.get("rotor_inertia"), out.rotor_inertia, boolean);
  Value motor = effects.get("motor");
  if (motor.present())
    out.motor = choose(motor, {MotorModel::none, MotorModel::quasi_static, MotorModel::full});
  out.contact = value_or(effects.get("contact"), out.contact, boolean);
  Value friction = effects.get("friction");
  out.friction = value_or(friction, out.friction, boolean);
  if (out.friction && !out.contact)
    friction.fail("needs effects.contact: true (friction acts at elbows resting on the table)");
  out.impacts = value_or(effects.get("impacts"), out.impacts, boolean);
  Value joint_friction = effects.get("joint_friction");
  out.joint_friction = value_or(joint_friction, out.joint_friction, boolean);
  Value stabilization = effects.get("stabilization");
  if (stabilization.present())
    out.stabilization = choose(
        stabilization, {Stabilization::none, Stabilization::baumgarte, Stabilization::projection});
  return out;
}

ValidityOptions read_validity(const Value& validity) {
  ValidityOptions out;
  if (!validity.present()) return out;
  validity.allow_keys({"energy_residual", "current_factor", "speed_factor", "rest_share"});
  out.energy_residual = value_or(validity.get("energy_residual"), out.energy_residual, positive);
  out.current_factor = value_or(validity.get("current_factor"), out.current_factor, positive);
  out.speed_factor = value_or(validity.get("speed_factor"), out.speed_factor, positive);
  Value share = validity.get("rest_share");
  if (share.present()) {
    out.rest_share = share.number();
    if (!(out.rest_share >= 0 && out.rest_share <= 1))
      share.fail("must be in [0, 1] (got " + significant(out.rest_share) + ")");
  }
  return out;
}

WarningOptions read_warnings(const Value& warnings) {
  WarningOptions out;
  if (!warnings.present()) return out;
  warnings.allow_keys({"saturation_share", "hand_error", "unplanned_contact_share"});
  const auto share_in_unit_interval = [&](const char* key, double& value) {
    const Value share = warnings.get(key);
    if (!share.present()) return;
    value = share.number();
    if (!(value >= 0 && value <= 1))
      share.fail("must be in [0, 1] (got " + significant(value) + ")");
  };
  share_in_unit_interval("saturation_share", out.saturation_share);
  share_in_unit_interval("unplanned_contact_share", out.unplanned_contact_share);
  out.hand_error = value_or(warnings.get("hand_error"), out.hand_error, positive);
  return out;
}

// Without simulation.duration a scene with a task runs to the task's end
// plus 0.5 s to settle, so sweeps over task.duration compare like with like.
double default_duration(const Value& simulation, const Value& task) {
  if (!task.present() || (simulation.present() && simulation.get("duration").present()))
    return positive(simulation.require("duration"));
  const double delay = value_or(task.get("start_delay"), 0.0, number);
  const double length = value_or(task.get("duration"), HandTask{}.duration, number);
  return delay + length + 0.5;
}

Options read_simulation(const Value& simulation, const Value& task) {
  // Optional with a task (its timing gives the duration); required otherwise.
  if (!simulation.present() && !task.present())
    simulation.fail("is required without a task (give simulation: {duration: ...})");
  Options out;
  out.duration = default_duration(simulation, task);
  if (!simulation.present()) return out;  // the defaults: 1 ms, auto, crba
  simulation.allow_keys({"duration", "step", "integrator", "dynamics", "rtol", "atol", "max_step"});
  Value step = simulation.get("step");
  out.step = value_or(step, 1e-3, positive);
  if (out.step > out.duration) {
    const std::string numbers =
        "(step " + significant(out.step) + " s, duration " + significant(out.duration) + " s)";
    if (step.present()) step.fail("must be <= simulation.duration " + numbers);
    simulation.get("duration").fail("must be >= simulation.step " + numbers);
  }
  // auto (or absent): rk4 until choose_integrator() decides (scenario_loader.cpp).
  Value integrator = simulation.get("integrator");
  if (!auto_integrator(simulation)) {
    using K = IntegratorKind;
    const std::vector<std::pair<int, std::string_view>> names = {
        {-1, "auto"},
        {int(K::euler), to_string(K::euler)},
        {int(K::semi_implicit_euler), to_string(K::semi_implicit_euler)},
        {int(K::rk4), to_string(K::rk4)},
        {int(K::dopri5), to_string(K::dopri5)},
        {int(K::ros34pw2), to_string(K::ros34pw2)}};
    out.integrator = static_cast<IntegratorKind>(choose(integrator, names));
  }
  read_error_control(simulation, out);
  Value dynamics = simulation.get("dynamics");
  if (dynamics.present())
    out.dynamics =
        choose(dynamics, {DynamicsMethod::walker_orin, DynamicsMethod::crba, DynamicsMethod::aba});
  return out;
}

Model::InitialState read_initial(const Value& initial, int dof) {
  Model::InitialState out;
  out.q = out.qd = out.current = Eigen::VectorXd::Zero(dof);
  if (!initial.present()) return out;
  initial.allow_keys({"q", "q_deg", "qd", "qd_deg", "current"});
  out.q = read_angles(initial, "q", dof);
  out.qd = read_angles(initial, "qd", dof);
  out.current = value_or(initial.get("current"), out.current,
                         [dof](const Value& v) { return per_joint(v, dof); });
  return out;
}

OutputSettings read_output(const Value& output, const std::string& name) {
  OutputSettings out;
  out.folder = "runs/" + name;
  if (!output.present()) return out;
  output.allow_keys(
      {"folder", "trajectory", "summary", "every", "video", "frames", "lossless_video"});
  Value folder = output.get("folder");
  out.folder = value_or(folder, out.folder, text);
  if (out.folder.empty()) folder.fail("must not be empty");
  out.trajectory = value_or(output.get("trajectory"), out.trajectory, boolean);
  out.summary = value_or(output.get("summary"), out.summary, boolean);
  Value every = output.get("every");
  long n = value_or(every, 1L, [](const Value& v) { return v.integer(); });
  if (n < 1) every.fail("must be >= 1 (got " + std::to_string(n) + ")");
  if (n > std::numeric_limits<int>::max())
    every.fail("is too large (got " + std::to_string(n) + ")");
  out.every = static_cast<int>(n);
  out.video = value_or(output.get("video"), out.video, boolean);
  out.frames = value_or(output.get("frames"), out.frames, boolean);
  out.lossless_video = value_or(output.get("lossless_video"), out.lossless_video, boolean);
  return out;
}

// joint_friction: {coulomb, breakaway, stribeck_velocity}, each one number for
// every joint or a list with one per joint. Needs effects.joint_friction.
std::vector<JointFriction> read_joint_friction(const Value& section, const Value& effect, int dof) {
  std::vector<JointFriction> out;
  const bool on = effect.present() && effect.boolean();
  if (!section.present()) {
    if (on) effect.fail("needs a joint_friction section ({coulomb: N m, breakaway: N m, ...})");
    return out;
  }
  if (!on) section.fail("needs effects.joint_friction: true (else it would be ignored)");
  section.allow_keys({"coulomb", "breakaway", "stribeck_velocity"});
  auto per_joint_values = [&](const char* key, double fallback, bool strictly_positive) {
    const Value v = section.get(key);
    Eigen::VectorXd x = Eigen::VectorXd::Constant(dof, fallback);
    if (!v.present()) return x;
    x = v.is_sequence() ? per_joint(v, dof) : Eigen::VectorXd::Constant(dof, v.number());
    for (int j = 0; j < dof; ++j)
      if (strictly_positive ? !(x[j] > 0) : !(x[j] >= 0))
        v.fail(std::string("must be ") + (strictly_positive ? "> 0" : ">= 0") + " (got " +
               significant(x[j]) + ")");
    return x;
  };
  const Eigen::VectorXd coulomb = per_joint_values("coulomb", 0.0, false);
  // Without breakaway: no Stribeck peak (breakaway = coulomb).
  const Eigen::VectorXd breakaway =
      section.get("breakaway").present() ? per_joint_values("breakaway", 0.0, false) : coulomb;
  const Eigen::VectorXd speed = per_joint_values("stribeck_velocity", 0.01, true);
  for (int j = 0; j < dof; ++j) {
    if (breakaway[j] < coulomb[j])
      section.get("breakaway")
          .fail("must be >= coulomb at every joint (joint " + std::to_string(j) + ": " +
                significant(breakaway[j]) + " < " + significant(coulomb[j]) + ")");
    out.push_back({coulomb[j], breakaway[j], speed[j]});
  }
  return out;
}

}  // namespace elbowsim::loader

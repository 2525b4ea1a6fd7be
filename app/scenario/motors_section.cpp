// motors: DC servo parameters (docs/model.md, Motors; paper eq. 16-27), a default for
// all joints plus optional per-joint overrides. Read and validated even when
// effects.motor is none, so that switching the motor on later cannot fail.
#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

// Overlays the keys given in `v` on `motor`. Returns the node that set the
// inductance, if any, for the full-model check below.
Value overlay_motor(const Value& v, Motor& motor) {
  v.allow_keys({"resistance", "inductance", "torque_constant", "gear_ratio", "rotor_inertia",
                "gear_friction", "voltage_limit", "current_limit", "rated_current", "efficiency",
                "backdrive_efficiency"});
  motor.resistance = value_or(v.get("resistance"), motor.resistance, positive);
  motor.inductance = value_or(v.get("inductance"), motor.inductance, non_negative);
  motor.torque_constant = value_or(v.get("torque_constant"), motor.torque_constant, positive);
  motor.gear_ratio = value_or(v.get("gear_ratio"), motor.gear_ratio, positive);
  motor.rotor_inertia = value_or(v.get("rotor_inertia"), motor.rotor_inertia, non_negative);
  motor.gear_friction = value_or(v.get("gear_friction"), motor.gear_friction, non_negative);
  motor.voltage_limit = value_or(v.get("voltage_limit"), motor.voltage_limit, positive);
  motor.current_limit = value_or(v.get("current_limit"), motor.current_limit, positive);
  motor.rated_current = value_or(v.get("rated_current"), motor.rated_current, positive);
  for (auto [key, target] : {std::pair{"efficiency", &motor.efficiency},
                             std::pair{"backdrive_efficiency", &motor.backdrive_efficiency}}) {
    const Value e = v.get(key);
    if (!e.present()) continue;
    *target = e.number();
    if (!(*target > 0 && *target <= 1))
      e.fail("must be in (0, 1] (got " + significant(*target) + ")");
  }
  return v.get("inductance");
}

// The full model integrates L di/dt = v - R i - Km qd: it needs L > 0.
void check_inductance(const Motor& motor, const Value& set_by, const Value& fallback,
                      MotorModel model) {
  if (model != MotorModel::full || motor.inductance > 0) return;
  (set_by.present() ? set_by : fallback)
      .fail("must be > 0 with effects.motor: full (got 0; use motor: quasi_static for L = 0)");
}

// Whether `v` (a motor entry) names the motor: gives one of its constants.
// A joint whose entries name none runs the built-in servo (Motor::builtin).
bool names_motor(const Value& v) {
  if (!v.present()) return false;
  for (const char* key :
       {"resistance", "inductance", "torque_constant", "gear_ratio", "rotor_inertia"})
    if (v.get(key).present()) return true;
  return false;
}

// The built-in servo comes with its rating; a scenario's own motor is rated
// only by its rated_current.
void mark_builtin(Motor& motor, bool named, bool rated) {
  motor.builtin = !named;
  if (motor.builtin && !rated) motor.rated_current = kBuiltinRatedCurrent;
}

}  // namespace

std::vector<Motor> read_motors(const Value& motors, const Model& model) {
  const auto n = static_cast<std::size_t>(model.dof);
  if (!motors.present()) {
    std::vector<Motor> builtin(n);
    for (Motor& m : builtin) mark_builtin(m, false, false);
    return builtin;
  }
  motors.allow_keys({"default", "joints"});

  Motor common;
  Value defaults = motors.get("default");
  Value common_inductance = defaults;  // replaced by the inductance node, if any
  if (defaults.present()) common_inductance = overlay_motor(defaults, common);
  std::vector<Motor> out(n, common);

  Value joints = motors.get("joints");
  std::vector<Value> items;
  if (joints.present()) {
    items = joints.items();
    if (items.size() != n)
      joints.fail("expected " + counted(static_cast<long long>(n), "entry", "entries") +
                  ", one per joint (got " + std::to_string(items.size()) + ")");
  }
  for (std::size_t i = 0; i < n; ++i) {
    Value inductance = common_inductance;
    if (!items.empty() && items[i].present()) {
      Value own = overlay_motor(items[i], out[i]);
      if (own.present()) inductance = own;
    }
    check_inductance(out[i], inductance, motors, model.effects.motor);
    const bool own = !items.empty() && items[i].present();
    mark_builtin(out[i], names_motor(defaults) || (own && names_motor(items[i])),
                 (defaults.present() && defaults.get("rated_current").present()) ||
                     (own && items[i].get("rated_current").present()));
  }
  return out;
}

}  // namespace elbowsim::loader

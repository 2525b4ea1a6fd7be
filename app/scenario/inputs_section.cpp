// inputs: open-loop profiles, one per joint: motor voltages [V] when a motor
// model is on, joint torques [N m] when effects.motor is none.
#include <string_view>
#include <utility>
#include <vector>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

using Kind = InputProfile::Kind;

// Profile kinds as written in scenario files.
const std::vector<std::pair<Kind, std::string_view>> kKinds{{Kind::zero, "zero"},
                                                            {Kind::constant, "constant"},
                                                            {Kind::sine, "sine"},
                                                            {Kind::table, "table"},
                                                            {Kind::steps, "steps"}};

// times strictly increasing [s]; values one per time.
void read_points(const Value& v, InputProfile& p) {
  v.allow_keys({"type", "times", "values"});
  Value times = v.require("times");
  Eigen::VectorXd t = times.numbers();
  if (t.size() == 0) times.fail("needs at least one time");
  std::vector<Value> items = times.items();
  for (Eigen::Index k = 1; k < t.size(); ++k) {
    if (!(t[k] > t[k - 1]))
      items[static_cast<std::size_t>(k)].fail("times must be strictly increasing (got " +
                                              significant(t[k - 1]) + " then " + significant(t[k]) +
                                              ")");
  }
  Eigen::VectorXd y = v.require("values").numbers(t.size(), "one per time");
  p.times.assign(t.data(), t.data() + t.size());
  p.values.assign(y.data(), y.data() + y.size());
}

// offset + amplitude sin(2 pi frequency t + phase)
void read_sine(const Value& v, InputProfile& p) {
  v.allow_keys({"type", "amplitude", "frequency", "phase", "offset"});
  p.amplitude = number(v.require("amplitude"));
  p.frequency = non_negative(v.require("frequency"));
  p.phase = value_or(v.get("phase"), 0.0, number);
  p.offset = value_or(v.get("offset"), 0.0, number);
}

InputProfile read_profile(const Value& v) {
  // Catch typos of any profile key first ("tpye" -> "type").
  v.allow_keys({"type", "value", "amplitude", "frequency", "phase", "offset", "times", "values"});
  InputProfile p;
  p.kind = choose(v.require("type"), kKinds);
  switch (p.kind) {
    case Kind::zero:
      v.allow_keys({"type"});
      break;
    case Kind::constant:
      v.allow_keys({"type", "value"});
      p.value = number(v.require("value"));
      break;
    case Kind::sine:
      read_sine(v, p);
      break;
    case Kind::table:
    case Kind::steps:
      read_points(v, p);
      break;
  }
  return p;
}

// A list of dof profiles, or a map {joint index: profile} with the rest zero.
std::vector<InputProfile> read_profiles(const Value& v, int dof) {
  std::vector<InputProfile> out(static_cast<std::size_t>(dof));
  if (v.is_sequence()) {
    std::vector<Value> items = v.items();
    if (items.size() != out.size())
      v.fail("expected " + counted(dof, "profile") + ", one per joint (got " +
             std::to_string(items.size()) + "); or give a map {joint index: profile}");
    for (std::size_t i = 0; i < items.size(); ++i) out[i] = read_profile(items[i]);
    return out;
  }
  if (!v.is_map())
    v.fail("expected a list of profiles, one per joint, or a map {joint index: profile}");
  std::vector<bool> seen(out.size(), false);
  for (const auto& [key, profile] : v.entries()) {
    long i = key.integer();
    if (i < 0 || i >= dof)
      key.fail("joint index out of range (got " + std::to_string(i) + "; valid: 0 .. " +
               std::to_string(dof - 1) + ")");
    if (seen[static_cast<std::size_t>(i)])
      key.fail("joint " + std::to_string(i) + " is given twice");
    seen[static_cast<std::size_t>(i)] = true;
    out[static_cast<std::size_t>(i)] = read_profile(profile);
  }
  return out;
}

}  // namespace

OpenLoopInputs read_inputs(const Value& inputs, const Model& model) {
  using Quantity = OpenLoopInputs::Quantity;
  OpenLoopInputs out;
  out.quantity = model.has_motor() ? Quantity::voltage : Quantity::torque;
  if (!inputs.present()) return out;
  inputs.allow_keys({"voltage", "torque"});
  Value voltage = inputs.get("voltage");
  Value torque = inputs.get("torque");
  if (voltage.exists() && torque.exists()) inputs.fail("give one of voltage or torque, not both");
  if (voltage.exists()) {
    if (!model.has_motor())
      voltage.fail("voltage inputs need a motor, but effects.motor is none (give torque inputs)");
    out.joints = read_profiles(voltage, model.dof);
  } else if (torque.exists()) {
    if (model.has_motor())
      torque.fail(std::string("torque inputs need effects.motor: none (it is ") +
                  to_string(model.effects.motor) + "; give voltage inputs)");
    out.joints = read_profiles(torque, model.dof);
  }
  return out;
}

}  // namespace elbowsim::loader

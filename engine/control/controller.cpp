#include "engine/control/controller.hpp"

#include "engine/control/plan.hpp"

namespace elbowsim {

const char* to_string(ControllerSpec::Kind k) {
  switch (k) {
    case ControllerSpec::Kind::open_loop: return "open_loop";
    case ControllerSpec::Kind::pd: return "pd";
    case ControllerSpec::Kind::pd_feedforward: return "pd_feedforward";
    case ControllerSpec::Kind::force: return "force";
  }
  return "?";
}

namespace {

double input_at(const Model& model, int joint, double t) {
  const auto& profiles = model.inputs.joints;
  return profiles.empty() ? 0.0 : profiles[static_cast<std::size_t>(joint)].at(t);
}

// PD (PID in a sampled loop) on the joint errors along the plan, in volts, plus the plan's
// feed-forward voltage for pd_feedforward and force control.
void track(const Controller& controller, Data& data, double t, ConstVec q, ConstVec qd) {
  const ControllerSpec& c = controller.spec;
  const Plan& plan = *controller.plan;
  plan.at(plan.q, t, data.q_desired);
  plan.at(plan.qd, t, data.qd_desired);
  data.voltage = c.kp.cwiseProduct(data.q_desired - q) + c.kd.cwiseProduct(data.qd_desired - qd);
  // The integral is the sampled loop's state, sized only with integral action
  // (start_digital_loop; sample() in digital_loop.cpp updates it).
  if (data.loop.integral.size() == q.size())
    data.voltage += c.ki.cwiseProduct(data.loop.integral);
  if (c.kind == ControllerSpec::Kind::pd) return;
  plan.at(plan.v_ff, t, data.v_feedforward);
  data.voltage += data.v_feedforward;
}

}  // namespace

void control_law(const Model& model, Data& data, double t, ConstVec q, ConstVec qd) {
  if (!model.has_motor()) {
    for (int j = 0; j < model.dof; ++j) data.actuation[j] = input_at(model, j, t);
    return;
  }
  const Controller* controller = data.controller.get();
  if (controller && controller->plan && controller->spec.kind != ControllerSpec::Kind::open_loop)
    return track(*controller, data, t, q, qd);
  for (int j = 0; j < model.dof; ++j) data.voltage[j] = input_at(model, j, t);
}

void command(const Model& model, Data& data, double t, ConstVec q, ConstVec qd) {
  if (model.has_motor() && sampled_loop(data)) {
    // Zero-order hold: the plan at t is still what the last sample left.
    data.voltage = data.loop.held;
    return;
  }
  control_law(model, data, t, q, qd);
}

}  // namespace elbowsim

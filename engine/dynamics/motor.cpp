#include "engine/dynamics/motor.hpp"

#include "engine/control/plan.hpp"

namespace elbowsim {

namespace {

double input_at(const Model& model, int joint, double t) {
  const auto& profiles = model.inputs.joints;
  return profiles.empty() ? 0.0 : profiles[static_cast<std::size_t>(joint)].at(t);
}

// Commanded voltages (before saturation) into data.voltage.
void command(const Model& model, Data& data, double t, ConstVec q, ConstVec qd) {
  const ControllerSpec& c = model.controller;
  if (c.kind == ControllerSpec::Kind::open_loop || !data.plan) {
    for (int j = 0; j < model.dof; ++j) data.voltage[j] = input_at(model, j, t);
    return;
  }
  const Plan& plan = *data.plan;
  plan.at(plan.q, t, data.q_desired);
  plan.at(plan.qd, t, data.qd_desired);
  // PD on the joint errors, in volts.
  data.voltage = c.kp.cwiseProduct(data.q_desired - q) + c.kd.cwiseProduct(data.qd_desired - qd);
  if (c.kind == ControllerSpec::Kind::pd) return;
  plan.at(plan.v_ff, t, data.v_feedforward);
  data.voltage += data.v_feedforward;
}

}  // namespace

void motor_stage(const Model& model, Data& data, double t, ConstVec q, ConstVec qd,
                 ConstVec current) {
  const int n = model.dof;
  if (!model.has_motor()) {
    for (int j = 0; j < n; ++j) data.actuation[j] = input_at(model, j, t);
    return;
  }
  command(model, data, t, q, qd);
  for (int j = 0; j < n; ++j) {
    const double v = saturate(data.voltage[j], model.voltage_limit[j]);
    const double back_emf = model.km[j] * qd[j];
    data.voltage[j] = v;
    if (model.has_current_state()) {
      data.current[j] = current[j];
      data.current_rate[j] = (v - model.resistance[j] * current[j] - back_emf) / model.inductance[j];
    } else {
      data.current[j] = (v - back_emf) / model.resistance[j];
    }
    data.actuation[j] = model.km[j] * data.current[j];
  }
}

}  // namespace elbowsim

#include "motor.hpp"

namespace elbowsim {

namespace {

double input_at(const Model& model, int joint, double t) {
  const auto& profiles = model.inputs.joints;
  return profiles.empty() ? 0.0 : profiles[static_cast<std::size_t>(joint)].at(t);
}

}  // namespace

void motor_stage(const Model& model, Data& data, double t, ConstVec qd,
                 ConstVec current) {
  const int n = model.dof;
  if (!model.has_motor()) {
    for (int j = 0; j < n; ++j) data.actuation[j] = input_at(model, j, t);
    return;
  }
  for (int j = 0; j < n; ++j) {
    const double v = saturate(input_at(model, j, t), model.voltage_limit[j]);
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

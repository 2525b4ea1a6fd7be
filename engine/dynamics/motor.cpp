#include "engine/dynamics/motor.hpp"

namespace elbowsim {

void motor_stage(const Model& model, Data& data, ConstVec qd, ConstVec current) {
  if (!model.has_motor()) return;
  for (int j = 0; j < model.dof; ++j) {
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

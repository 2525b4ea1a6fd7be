#include "engine/dynamics/motor.hpp"

#include <algorithm>
#include <limits>

namespace elbowsim {

void motor_stage(const Model& model, Data& data, ConstVec qd, ConstVec current) {
  if (!model.has_motor()) return;
  data.gear_loss_power = 0.0;
  for (int j = 0; j < model.dof; ++j) {
    double v = saturate(data.voltage[j], model.voltage_limit[j]);
    const double back_emf = model.km[j] * qd[j];
    // Current limit: the voltage window in which R i = v - back-EMF stays
    // within +-R i_max. Quasi-static: |i| <= i_max exactly. Full model: then
    // L di/dt <= R (i_max - i), so a current inside the limit stays inside.
    if (model.current_limit[j] < std::numeric_limits<double>::infinity()) {
      const double window = model.resistance[j] * model.current_limit[j];
      v = std::clamp(v, back_emf - window, back_emf + window);
    }
    data.voltage[j] = v;
    if (model.has_current_state()) {
      data.current[j] = current[j];
      data.current_rate[j] = (v - model.resistance[j] * current[j] - back_emf) / model.inductance[j];
    } else {
      data.current[j] = (v - back_emf) / model.resistance[j];
    }
    const double motor_torque = model.km[j] * data.current[j];
    data.actuation[j] = motor_torque;
    if (!model.gear_losses) continue;
    // The gear passes efficiency x the torque when the motor drives the load
    // (power toward the joint), torque / backdrive_efficiency when the load
    // drives the motor; what it keeps is its loss. At rest it counts as driving.
    data.actuation[j] = motor_torque * qd[j] >= 0 ? model.gear_efficiency[j] * motor_torque
                                                  : motor_torque / model.backdrive_efficiency[j];
    data.gear_loss_power += (motor_torque - data.actuation[j]) * qd[j];
  }
}

}  // namespace elbowsim

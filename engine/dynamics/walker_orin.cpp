#include "engine/dynamics/walker_orin.hpp"

#include "engine/dynamics/rnea.hpp"

namespace elbowsim {

void mass_matrix_walker_orin(const Model& model, Data& data) {
  const InverseDynamicsTerms inertia_only{false, false, false, false};
  for (int i = 0; i < model.dof; ++i) {
    data.unit.setZero();
    data.unit[i] = 1.0;
    inverse_dynamics(model, data, data.zero, data.unit, inertia_only, data.mass_matrix.col(i));
  }
}

void bias_torques(const Model& model, Data& data, ConstVec qd) {
  inverse_dynamics(model, data, qd, data.zero, InverseDynamicsTerms{}, data.bias);
  data.bias_rates_serial = data.kinematics_serial;
  data.bias_rates_qd = qd;
}

}  // namespace elbowsim

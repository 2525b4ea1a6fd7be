#include "engine/dynamics/applied_torques.hpp"

#include "engine/dynamics/joint_friction.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

double applied_torques(const Model& model, Data& data, ConstVec qd) {
  double hand_power = 0;
  if (!model.hand_load.force.isZero()) {  // the same test as energy_group_present(hand_force)
    point_jacobian(model, data, model.hand_link, model.hand_point, data.contact.J3);
    data.actuation.noalias() += data.contact.J3.transpose() * model.hand_load.force;
    hand_power = model.hand_load.force.dot(data.contact.J3 * qd);
  }
  if (model.effects.joint_friction)
    sliding_friction_torques(model, data, qd);
  else
    data.tau_applied = data.actuation;
  return hand_power;
}

}  // namespace elbowsim

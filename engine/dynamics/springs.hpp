// Joint springs (Model::springs; docs/model.md, "Joint springs"): conservative
// torsion springs at the joints, a counterbalance. Their torque is a
// generalized force like gravity's: inverse dynamics (rnea) and ABA take it
// in, so the plan's feed-forward knows the springs the controller's model has.
#pragma once

#include "engine/eigen_types.hpp"
#include "engine/model.hpp"

namespace elbowsim {

// The torque spring `s` exerts on its joint at angle q [N m].
inline double spring_torque(const JointSpring& s, double q) {
  return s.torque - s.stiffness * (q - s.at);
}

// Adds `sign` times the torque the springs exert on each joint at q to `tau` [n].
inline void add_spring_torques(const Model& model, ConstVec q, double sign,
                               Eigen::Ref<Eigen::VectorXd> tau) {
  for (const JointSpring& s : model.springs) tau[s.joint] += sign * spring_torque(s, q[s.joint]);
}

// Their potential at q [J]: sum of -torque (q - at) + stiffness (q - at)^2 / 2.
double spring_energy(const Model& model, ConstVec q);

}  // namespace elbowsim

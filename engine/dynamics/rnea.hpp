// Recursive Newton-Euler inverse dynamics (paper eq. 50-51, Luh-Walker-Paul
// form in world coordinates).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Which terms of eq. (51) to include beyond (M + Jm) qdd. Each term also needs
// its effect switched on in the model (gravity, damping); the Jm qdd term is
// included whenever the model has rotor inertia.
struct InverseDynamicsTerms {
  bool velocity = true;  // Coriolis/centrifugal h(q, qd); off means qd is treated as zero
  bool gravity = true;   // G(q)
  bool damping = true;   // (D + Dm) qd
  bool springs = true;   // the joint springs' torque (at data.kinematics_q), subtracted
};

// tau [n, N m] = (M(q) + Jm) qdd + h(q, qd) + G(q) + (D + Dm) qd - tau_springs(q),
// the joint torques that produce qdd. Needs forward_kinematics(q). Allocates nothing.
void inverse_dynamics(const Model& model, Data& data, ConstVec qd,
                      ConstVec qdd, InverseDynamicsTerms terms,
                      Eigen::Ref<Eigen::VectorXd> tau);

}  // namespace elbowsim

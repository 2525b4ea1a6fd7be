// Articulated-body algorithm: unconstrained forward dynamics in O(n), with the
// rotor inertia Jm entering as joint armature.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// qdd [n] = (M + Jm)^-1 (tau - h - G - (D + Dm) qd) for applied joint torques
// tau [n, N m]. Needs forward_kinematics(q). Allocates nothing.
void forward_dynamics_aba(const Model& model, Data& data, ConstVec qd,
                          ConstVec tau, Eigen::Ref<Eigen::VectorXd> qdd);

}  // namespace elbowsim

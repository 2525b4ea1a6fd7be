// Unconstrained forward dynamics by the method the scene selects.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// qdd [n] for applied joint torques tau [n, N m] (eq. 29 without contacts):
// (M + Jm) qdd = tau - h - G - (D + Dm) qd. walker_orin and crba build M and
// factor it (Cholesky); aba runs the articulated-body recursion.
// Needs forward_kinematics(q).
void forward_dynamics(const Model& model, Data& data, ConstVec qd,
                      ConstVec tau, Eigen::Ref<Eigen::VectorXd> qdd);

// Same, with an explicit method (tests and benchmarks compare them).
void forward_dynamics(const Model& model, Data& data, DynamicsMethod method,
                      ConstVec qd, ConstVec tau,
                      Eigen::Ref<Eigen::VectorXd> qdd);

}  // namespace elbowsim

// Articulated-body algorithm: unconstrained forward dynamics in O(n), with the
// rotor inertia Jm entering as joint armature.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// qdd [n] = (M + Jm)^-1 (tau - h - G - (D + Dm) qd) for applied joint torques
// tau [n, N m]. Needs forward_kinematics(q). Allocates nothing.
void forward_dynamics_aba(const Model& model, Data& data, ConstVec qd,
                          ConstVec tau, Eigen::Ref<Eigen::VectorXd> qdd);

// The inward pass of ABA without velocities or torques: the articulated
// inertias' projections data.U [n] and data.D [n] (+ Jm) at the current q,
// all that the response below needs. Needs forward_kinematics(q). O(n).
void articulated_inertias(const Model& model, Data& data);

// x [n] = (M + Jm)^-1 tau for joint torques tau [n] (no velocity, gravity or
// damping terms), from the U and D of the last articulated_inertias() or
// forward_dynamics_aba() at the same q: one inward and one outward sweep of
// 6-vectors, O(n); the inward sweep starts at tau's last non-zero entry
// (a contact row's torques end at its link).
// x may alias tau.
void aba_response(const Model& model, const Data& data, ConstVec tau,
                  Eigen::Ref<Eigen::VectorXd> x);

}  // namespace elbowsim

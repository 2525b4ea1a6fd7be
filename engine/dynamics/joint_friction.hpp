// Dry friction at the joints (effects.joint_friction): a sliding joint is
// resisted by the Stribeck curve tau(w) = tau_c + (tau_s - tau_c)
// exp(-(w/w_s)^2) against its direction; a stuck joint does not move
// (qdd_j = 0) and its friction is whatever holds it, while that stays within
// tau_s. Which joints slide or stick is decided per step
// (run/joint_stick_slip.hpp); here the dynamics for given modes.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// [N m] >= 0: the friction torque of a joint sliding at |speed| (the Stribeck curve).
double sliding_friction(const JointFriction& f, double speed);

// Whether joint friction holds any joint stuck (data.joint_mode 0). Without
// effects.joint_friction never (joint_mode is then all 0 but means nothing).
bool any_joint_stuck(const Model& model, const Data& data);

// data.joint_mass = data.mass_matrix with the rows and columns of the joints
// stuck in data.joint_mode replaced by the identity's: factored, it gives
// qdd_S = 0 and the free joints' accelerations of the locked arm.
void lock_stuck_joints(Data& data);

// The friction of the sliding joints in the modes data.joint_mode into
// data.joint_friction_torque (stuck joints: 0 until their holding torque is
// known) and data.tau_applied = data.actuation + that friction.
void sliding_friction_torques(const Model& model, Data& data, ConstVec qd);

// The arm's accelerations with joint friction (no resting elbow), after
// sliding_friction_torques: stuck joints locked (qdd_j = 0, by M with their
// rows and columns replaced by the identity), data.joint_friction_torque[j]
// the torque that holds them. Fills data.qdd. Needs forward_kinematics(q).
void joint_friction_dynamics(const Model& model, Data& data, ConstVec qd);

// With resting elbows, after the constrained solve (which locks stuck joints,
// contact/constrained_dynamics.hpp): what holds each stuck joint,
// M_j qdd - (tau_applied - B)_j - (Jf^T f)_j, into data.joint_friction_torque.
void holding_torques(const Model& model, Data& data);

}  // namespace elbowsim

// The joint torques that drive the arm besides gravity, Coriolis and
// damping: the motors' (data.actuation, from the motor stage), the hand
// force's J^T F and the sliding joints' dry friction. One function, so that
// the derivative and the contact decisions see the same torques.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// After forward kinematics and the motor stage at (q, qd): data.actuation
// gains J_hand^T F (hand_load.force), and data.tau_applied = actuation + the
// friction of the joints sliding in data.joint_mode (effects.joint_friction;
// a stuck joint gets 0 here, its holding torque comes out of the solve).
// Returns the hand force's power F . v_hand [W] (0 without one).
double applied_torques(const Model& model, Data& data, ConstVec qd);

}  // namespace elbowsim

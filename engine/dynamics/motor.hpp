// DC servo motors (paper eq. 16-27), per joint, reflected through the gear:
// Km = K k, Jm = Im k^2, Dm = dm k^2 (docs/model.md, "Motors").
//   full:          L di/dt = v - R i - Km qd          (current is state)
//   quasi_static:  i = (v - Km qd) / R                (L -> 0)
//   torque on the joint: Km i; Jm qdd and Dm qd enter the arm dynamics.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Clamp a commanded voltage to [-limit, limit].
inline double saturate(double v, double limit) { return v < -limit ? -limit : (v > limit ? limit : v); }

// The motors under the command the controller left in data.voltage
// (control/controller.hpp), for joint rates qd [n] and, with the full model,
// motor currents `current` [n]. Saturates data.voltage in place and fills
// data.current (quasi_static: computed; full: copied), data.actuation = Km i
// and data.current_rate (full model only). Without motors it does nothing:
// the command is already the joint torque in data.actuation.
void motor_stage(const Model& model, Data& data, ConstVec qd, ConstVec current);

}  // namespace elbowsim

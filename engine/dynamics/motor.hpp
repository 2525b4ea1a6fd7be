// DC servo motors (paper eq. 16-27, DESIGN.md §1), per joint, reflected
// through the gear: Km = K k, Jm = Im k^2, Dm = dm k^2.
//   full:          L di/dt = v - R i - Km qd          (current is state)
//   quasi_static:  i = (v - Km qd) / R                (L -> 0)
//   torque on the joint: Km i; Jm qdd and Dm qd enter the arm dynamics.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Clamp a commanded voltage to [-limit, limit].
inline double saturate(double v, double limit) { return v < -limit ? -limit : (v > limit ? limit : v); }

// Controller, inputs and motors at time t for the state (q, qd) and, with the
// full model, motor currents `current`. Fills data.voltage (saturated),
// data.current (quasi_static: computed; full: copied), data.actuation (Km i,
// or the input torque without motors) and data.current_rate (full model only).
void motor_stage(const Model& model, Data& data, double t, ConstVec q, ConstVec qd,
                 ConstVec current);

}  // namespace elbowsim

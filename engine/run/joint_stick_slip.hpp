// Which joints stick and which slide (effects.joint_friction), decided at
// each step's start and held over the step, so the friction torque is smooth
// inside it; a change inside a step (a sliding joint stopping, a stuck one
// breaking away) is located and the step cut there (run/event_location.hpp).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// [rad/s] a sliding joint this slow at a step's start sticks (its speed is
// set to 0: a located stop leaves ~|qdd| x locate_tolerance). Stated, not tuned.
constexpr double kJointStickSpeed = 1e-6;

// At a step's start (and at reset): a joint moving faster than
// kJointStickSpeed slides its way, as does a joint without friction
// (breakaway 0) at any speed; the others stick (speed set to 0) unless
// the torque that would hold them exceeds their breakaway torque, in which
// case they slide against it (the largest excess first, until all hold).
void decide_joint_modes(const Model& model, Data& data);

// After the step from data.x_start (t0): the first sliding joint whose speed
// turned or stuck joint whose holding torque left +-breakaway, located within
// model.contact.locate_tolerance; the step is redone up to it. None: nothing.
void locate_joint_event(const Model& model, Data& data, double t0);

}  // namespace elbowsim

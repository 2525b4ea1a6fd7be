// Contact detection at the state in data.x, the first of contact's three
// parts (detection -> rows -> solve): Bullet's signed distance, table normal
// and surface point for every elbow sphere (collision.hpp), kept in
// data.contact.detected / normal / surface for the stages of the step.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Forward kinematics at q of data.x, then the distances of every elbow.
// Needs the run's collision world (data.contact.world, built by reset()).
void detect_contacts(const Model& model, Data& data);

// Normal velocity [m/s] of elbow k's centre at the rates of data.x, along the
// table normal last detected (< 0 approaching). Needs forward_kinematics.
double normal_speed(const Model& model, const Data& data, int elbow);

}  // namespace elbowsim

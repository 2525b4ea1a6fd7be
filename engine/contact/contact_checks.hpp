// Checks after a contact step: how far the resting slots drift off their
// constraints (max |C|, max |Cd| over the run, in data.contact). Whether any
// part of the arm is inside the table is a validity check (run/validity.hpp).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Needs the detection current at the step's final state (detect_contacts).
void check_contacts(const Model& model, Data& data);

}  // namespace elbowsim

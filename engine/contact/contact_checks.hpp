// Checks after a contact step: how far the resting elbows drift off their
// constraints (max |C|, max |Cd| over the run), and links whose capsules
// reach into the table (a warning when a link enters a box).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Needs the detection current at the step's final state (detect_contacts).
void check_contacts(const Model& model, Data& data);

}  // namespace elbowsim

// Landings and releases inside a step (contact.events: locate). After the
// step from data.x_start (time t0) to data.x, an elbow that went into the
// table has landed, and a resting one whose normal force turned negative has
// released. The step is redone up to the earliest such event, found by root
// finding on the event function (distance for a landing, force for a
// release), so the next step starts at the event.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Redoes the step up to the first event within model.contact.locate_tolerance
// and records a release there (a landing is handled by the impact stage). With
// contact.events: step it does nothing: events fall on step boundaries.
// Leaves the detection current at the step's final state.
void locate_first_event(const Model& model, Data& data, double t0);

}  // namespace elbowsim

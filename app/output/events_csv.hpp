// events.csv: every landing and release of a run, in time order; the contact is named
// as contact/primitives.hpp slot_name() names it (an elbow by its name).
#pragma once

#include <iosfwd>
#include <vector>

#include "engine/model.hpp"
#include "engine/run/step_log.hpp"

namespace elbowsim {

void write_events_csv(std::ostream& out, const Model& model, const std::vector<ContactEvent>& events);

}  // namespace elbowsim

// events.csv: every elbow landing and release of a run, in time order.
#pragma once

#include <iosfwd>
#include <vector>

#include "engine/model.hpp"
#include "engine/run/step_log.hpp"

namespace elbowsim {

void write_events_csv(std::ostream& out, const Model& model, const std::vector<ContactEvent>& events);

}  // namespace elbowsim

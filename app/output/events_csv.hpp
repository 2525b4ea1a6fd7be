// events.csv: every elbow landing and release of a run, in time order.
#pragma once

#include <iosfwd>

#include "engine/model.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

void write_events_csv(std::ostream& out, const Model& model, const ContactLog& log);

}  // namespace elbowsim

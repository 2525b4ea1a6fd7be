// Recording a run: one row of the trajectory table per recorded step, read
// from Data after evaluate_outputs(); the columns depend on the model.
#pragma once

#include "engine/data.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

// The columns of a run's trajectory (name and unit each).
std::vector<Column> trajectory_columns(const Model& model, bool has_plan);

// Appends one row at the state in data (stage outputs evaluated, contacts
// detected there).
void record_sample(const Model& model, const Data& data, Recording& rec);

}  // namespace elbowsim

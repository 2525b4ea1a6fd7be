// Recording a run: one row of the trajectory table per recorded step, read
// from Data after evaluate_outputs() and written column by column through the
// trajectory layout (recording/trajectory_layout.hpp).
#pragma once

#include "engine/data.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

// The layout of a run of `model`; desired_hand: the run follows a plan (a
// hand task), so the desired hand and the hand error are recorded.
TrajectoryLayout trajectory_layout(const Model& model, bool desired_hand);

// [bytes] What a run of `model` recording every `every`-th step (of
// options.step) would hold in memory: rows x columns x 8 (the table is kept
// until the run ends). Rows beyond 1e18 count as 1e18 (no overflow).
double recording_bytes_estimate(const Model& model, int every, bool desired_hand);

// Appends one row at the state in data (stage outputs evaluated, contacts
// detected there). Every column of rec.layout is written.
void record_sample(const Model& model, const Data& data, Recording& rec);

}  // namespace elbowsim

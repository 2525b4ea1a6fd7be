// Which elbows rest on the table for the coming step (paper eq. 39-45: the
// rows of M* that are on). The elbows that touch (distance <= touch_distance,
// not separating) or rest form a small LCP on the Delassus matrix,
//   f >= 0, normal acceleration w = A f + b >= 0, f . w = 0,
// whose solution is the active set: rows of M* that stay on for the whole step
// (so the step is smooth and keeps its order).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Detects contacts at the state in data.x (time data.t) and sets
// data.contact.active and .resting; a row switched on or off is a landing or
// release event in data.log. Returns false, with data.failure set, when no
// valid set exists (Painleve's paradox with friction, or no complementary
// solution). Dependent rows are solved for minimum-norm forces, with a
// warning the first time. Allocates nothing.
bool select_active_set(const Model& model, Data& data);

}  // namespace elbowsim

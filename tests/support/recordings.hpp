// Recordings written by hand for the report and renderer tests: a layout's
// rows of zeros, then the columns a test cares about set by layout index.
#pragma once

#include <cstddef>

#include "engine/recording/recording.hpp"

namespace elbowsim::testing {

inline Recording zero_recording(TrajectoryLayout::Groups groups, std::size_t rows) {
  Recording rec{TrajectoryLayout(std::move(groups))};
  rec.values.assign(rows * rec.columns().size(), 0.0);
  return rec;
}

inline void set(Recording& rec, std::size_t row, int column, double value) {
  rec.values[row * rec.columns().size() + static_cast<std::size_t>(column)] = value;
}

}  // namespace elbowsim::testing

// trajectory.csv: one row per recorded sample, a header of "name [unit]".
#pragma once

#include <iosfwd>
#include <string>

#include "engine/recording/recording.hpp"

namespace elbowsim {

void write_trajectory_csv(std::ostream& out, const Recording& recording);

// Reads what write_trajectory_csv wrote (renderer, report). Throws
// std::runtime_error naming `file` and the line of a malformed row.
Recording read_trajectory_csv(std::istream& in, const std::string& file);

}  // namespace elbowsim

// trajectory.csv: one row per recorded sample, a header of "name [unit]".
#pragma once

#include <iosfwd>

#include "engine/recording.hpp"

namespace elbowsim {

void write_trajectory_csv(std::ostream& out, const Recording& recording);

}  // namespace elbowsim

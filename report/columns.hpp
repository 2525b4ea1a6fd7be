// Series read out of a recorded trajectory through its layout
// (engine/recording/trajectory_layout.hpp), and the few series the report
// derives from them (electrical power, running integrals, resting intervals).
#pragma once

#include <string>
#include <vector>

#include "engine/recording/recording.hpp"
#include "report/plot/plot.hpp"

namespace elbowsim::report {

// The values of column `index` (from rec.layout), one per row; empty when index < 0.
std::vector<double> column(const Recording& rec, int index);

// The name and unit of column `index` ("" when index < 0).
std::string column_name(const Recording& rec, int index);
std::string column_unit(const Recording& rec, int index);

// Electrical power into the motors, sum_j v_j i_j [W], per row; empty without
// motor columns.
std::vector<double> electrical_power(const Recording& rec);

// Running trapezoid integral of y over t, starting at 0 (same length). A
// non-finite sample adds nothing.
std::vector<double> running_integral(const std::vector<double>& t, const std::vector<double>& y);

// Where `state` >= 0.5 (a rest_<elbow> column): each stretch from its first
// sample to the next sample after its last (sample and hold).
std::vector<plot::Interval> intervals_on(const std::vector<double>& t,
                                         const std::vector<double>& state);

}  // namespace elbowsim::report

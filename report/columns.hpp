// Reading series out of a recorded trajectory by column name, and the few
// series the report derives from them (electrical power, running integrals,
// resting intervals).
#pragma once

#include <string>
#include <vector>

#include "engine/recording/recording.hpp"
#include "report/plot/plot.hpp"

namespace elbowsim::report {

// The values of a named column, one per row; empty when there is no such column.
std::vector<double> column(const Recording& rec, const std::string& name);

// The unit of a named column ("" when absent).
std::string column_unit(const Recording& rec, const std::string& name);

// Columns named prefix + 0, 1, 2, ... in order ("q" -> q0, q1; not qd0).
std::vector<std::string> indexed_columns(const Recording& rec, const std::string& prefix);

// Elbow names, from the fn_<elbow>, d_<elbow> and rest_<elbow> columns, in column order.
std::vector<std::string> elbow_names(const Recording& rec);

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

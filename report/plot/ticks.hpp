// Axis ticks at round numbers: 1-2-5 x 10^k steps on linear axes, whole
// decades (every 1, 2, 5, 10, ... decades) on log axes, with their labels.
// Pure arithmetic, no drawing: plot.cpp places what these return.
#pragma once

#include <string>
#include <vector>

namespace elbowsim::plot {

struct Ticks {
  double lo = 0, hi = 1;            // axis limits (data units), lo < hi
  std::vector<double> major;        // tick values in [lo, hi], ascending
  std::vector<std::string> labels;  // one per major tick (UTF-8, "10⁻³" on log axes)
  std::vector<double> minor;        // log axes: 2..9 x 10^k between majors; else empty
};

// The 1-2-5 x 10^k step nearest range / target (range > 0, target >= 1).
double nice_step(double range, int target);

// Ticks for data in [lo, hi] (any order; a non-finite bound gives [0, 1]; a
// constant widens to +-10 %, or +-1 around 0). `loose` moves the limits out to
// the enclosing ticks; tight keeps [lo, hi] and ticks the round values inside.
Ticks linear_ticks(double lo, double hi, int target = 6, bool loose = true);

// Decade ticks for positive data in [lo, hi]; limits snap out to whole
// decades (a single power of ten widens by one decade each way). Over at most
// two decades 2×10ⁿ and 5×10ⁿ are labelled as well. Bounds that are not
// positive and finite give [1, 10].
Ticks log_ticks(double lo, double hi, int target = 8);

// A linear tick label with enough digits to tell ticks `step` apart: fixed
// point ("0.25", "-3") when the axis' largest |value| `magnitude` is in
// [1e-3, 1e5), else with the axis' power of ten ("1.5×10⁻⁵", "0.5×10⁷").
std::string format_linear(double value, double step, double magnitude);

// "10⁻³", "10⁰", "10¹²".
std::string format_power_of_ten(int exponent);

}  // namespace elbowsim::plot

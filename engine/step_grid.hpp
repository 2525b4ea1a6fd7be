// "On the step grid": whether a time has reached an instant of a fixed grid
// (the digital loop's sample instants k T, the recorded rows k x interval, the
// run's end, the renderer's frames k / fps), and whether what is left before
// one is worth a step. Every such decision of the engine, the renderer and the
// application goes through here, with a tolerance that is a share of the
// grid's spacing (the step), never an absolute time: a 1 us step and a 10 ms
// step round alike.
//
// Three shares, because they bound three different errors. Each is the value
// the code used before this header. kRow or kFixedEnd set to kRounding changes
// shipped scenes' outputs (golden hashes, measured); kRounding set to kRow
// changes none of them but moves a sample off its instant (below). The tests,
// tests/engine/test_step_grid.cpp, fail for each of these changes:
//   kRounding  1e-9  the rounding of one operation: an instant computed as k T
//                    or k x interval, a step cut to end on it (h = instant - t),
//                    a period 1 / rate. A few ulps: 1e-10 of a 1 ms step at
//                    t = 1000 s. Used where t was just cut to the instant (sample
//                    instants, an adaptive run's end and rows). At 1e-6 no shipped
//                    scene changes, but a sample would be taken, and an adaptive
//                    row recorded, up to 1e-6 of a step before its instant.
//   kRow       1e-6  the rows: between rows a fixed step's t accumulates the
//                    rounding of every step's sum (scenarios/hard/long_rest.yaml:
//                    10^4 steps between rows end 2.4e-7 of a step short of
//                    t = 1000 s), and a sample instant coincides with a row only
//                    up to rounding (1e-13 s, 1e-9 of a 1e-4 s step, recorded the
//                    row twice: commit 7fafad0). At 1e-9 scenarios/hard/long_chain
//                    takes one sliver step more (10001 steps, not 10000).
//   kFixedEnd  1e-3  the end of a fixed-step run: less than a thousandth of a
//                    step left is not stepped. At 1e-9, long_rest's last 2.4e-7
//                    of a step becomes a step and a row; at 1e-6 no shipped scene
//                    changes but a duration 1e-4 of a step past a whole number of
//                    steps takes a sliver step. (An adaptive run ends on the
//                    duration itself, adaptive_limit, and uses kRounding.)
#pragma once

#include <algorithm>
#include <cmath>

namespace elbowsim::step_grid {

inline constexpr double kRounding = 1e-9;  // [share of a step]
inline constexpr double kRow = 1e-6;       // [share of a step]
inline constexpr double kFixedEnd = 1e-3;  // [share of a step]

// Whether the time `left` before an instant is within `share` of a step: the
// instant is reached (the run's end: finished(); a sample: no step to it).
inline bool reached(double left, double step, double share = kRounding) {
  return left <= share * step;
}

// Whether time `a` is not earlier than `b`, up to rounding (kRounding of a step).
inline bool not_earlier(double a, double b, double step) { return a >= b - kRounding * step; }

// Whether time `a` is not later than `b`, up to rounding (kRounding of a step).
inline bool not_later(double a, double b, double step) { return a <= b + kRounding * step; }

// Whether a period is shorter than a step by more than rounding (a sample
// period of 1 / rate against the same step must pass).
inline bool shorter_than_step(double period, double step) {
  return period < step * (1 - kRounding);
}

// The whole number of grid spacings within `spacings` (a span divided by the
// spacing): a span a rounding short of a whole number still counts it.
inline double whole_spacings(double spacings) { return std::floor(spacings + kRounding); }

// Rows (k x interval, a whole number of steps apart): the tolerance that
// cuts a step to a row and recognises a step's end as a row.
inline double row_tolerance(double step) { return kRow * step; }

// The index k of the first row k x interval after t, t itself within
// row_tolerance of a row counting as that row (so the next one is k + 1).
inline double next_row(double t, double interval, double step) {
  return std::floor((t + row_tolerance(step)) / interval) + 1;
}

// Whether t lies on row k (k x interval), within row_tolerance.
inline bool on_row(double t, double k, double interval, double step) {
  return std::abs(t - k * interval) <= row_tolerance(step);
}

// Two recorded times read back (trajectory.csv prints 12 significant digits,
// summary.json 17; two runs reach a row by different sums of steps) name the
// same instant when they differ by at most 1e-9 of max(1 s, |t|): the
// printing's 5e-13 relative and the rows' rounding are far below it; rows are
// 1 ms or more apart in the shipped scenes, 1000 times the tolerance at
// t = 1000 s. Not a share of a step: a file does not say its step.
inline constexpr double kRecordedTime = 1e-9;  // [relative to max(1 s, |t|)]

inline double recorded_time_tolerance(double t) {
  return kRecordedTime * std::max(1.0, std::abs(t));
}

inline bool same_recorded_time(double a, double b) {
  return std::abs(a - b) <= recorded_time_tolerance(b);
}

}  // namespace elbowsim::step_grid

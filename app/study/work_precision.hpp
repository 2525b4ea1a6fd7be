// What accuracy costs in time (elbowsim accuracy): a work-precision study of
// one scenario, in the style of Hairer & Wanner's test sets and the
// DifferentialEquations.jl benchmarks.
//
// For each variant: a reference run (dopri5 at rtol 1e-11, shown converged by
// a second run at 1e-10: their difference is the reference's uncertainty),
// then every method over a range of settings — fixed steps h = step / m for
// m = 1, 2, 3, 4, 6, 8, ... (rows stay at the same times), adaptive
// tolerances rtol = r0 10^-k — each timed (CPU time of the simulation without
// the controller's plan, which every run shares: median of repeats) and
// compared with the reference at every recorded row. At the
// scene's own setting the alternatives of equal accuracy are timed too:
// dynamics methods, constrained solvers, event handling.
#pragma once

#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim::study {

// Timings: from kMinTimedForInterval on (the fewest whose median has a 95 %
// interval), a setting is timed again until that interval lies within
// kTimingPrecision of the median, at most kMaxRepeats times or kTimingBudget; fewer requested
// repeats are taken as they are, without an interval.
constexpr int kMinTimedForInterval = 6;
constexpr double kTimingPrecision = 0.05;
constexpr int kMaxRepeats = 100;
constexpr double kTimingBudget = 30;  // [s] of CPU per setting, then its interval is what it is

struct WorkPrecisionOptions {
  std::vector<IntegratorKind> methods;  // empty: all five
  int points = 6;                       // settings per method (>= 2)
  int repeats = 10;                     // timings per setting at least (a run over 2 s: once)
  bool alternatives = true;             // time the dynamics methods, solvers and event modes
  const std::atomic<bool>* stop = nullptr;  // interrupt: no new run starts once set
  std::function<void(const std::string&)> progress;  // one line per finished run
};

// The reference run itself is not valid: the scene cannot be integrated.
class ReferenceInvalid : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Errors of a run against the reference, over their common recorded rows.
struct RunErrors {
  double angle_final = 0;  // [rad] max_j |q_j - q_ref_j| at the last row
  double angle_max = 0;    // [rad] the same, max over rows
  double hand_max = 0;     // [m] |hand - hand_ref| max over rows
  double hand_rms = 0;     // [m] its RMS over rows
  double force_max = 0;    // [N] max |f_n - f_n_ref| over rows and contact columns; NaN: no contact
  double event_time = 0;   // [s] max |t - t_ref| of landings/releases; NaN: none; inf: they differ
  long rows = 0;           // rows compared
};

// Throws std::invalid_argument when the rows are not at the same times.
RunErrors compare_runs(const RunResult& run, const RunResult& reference);

// The study of `scenario` (one variant, or one without variants), as JSON:
// reference, points (one per method and setting), alternatives. Null when
// options.stop was raised (nothing half-done is returned). Throws
// ReferenceInvalid when the reference run is not valid.
nlohmann::ordered_json work_precision(const Scenario& scenario, const WorkPrecisionOptions& options);

// The settings tried for a method: the steps (fixed) or rtols (adaptive).
std::vector<double> method_settings(IntegratorKind kind, double step, int points);

}  // namespace elbowsim::study

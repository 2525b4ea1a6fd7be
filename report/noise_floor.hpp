// When two runs differ in a number and when only by noise. Each summary.json
// number is a result (physics), a numerics check (how well the integration
// went), a timing or cost measurement of the computer, or a setting (an
// input). A result or numerics difference counts only above a noise floor:
//
//   - twice the change at half the step, where every run measured it
//     (--check-step: summary.json step_check), as the accuracy floor;
//   - else 1 % of the quantity's scale: the largest magnitude of that
//     quantity (all joints, all elbows, all hand-error measures) in any of
//     the runs; for energies 0.1 % of the energy that flowed (the sources of
//     the energy account, report/energy_flow.hpp; 20 x the 5e-5 by which the
//     experiment's energies move at half the step), so that a kinetic energy
//     of 1e-19 J in a run that moved joules reads "same";
//   - quantities that should be zero have an absolute floor: constraint
//     drift 1 nm (1 nm/s), a relative balance residual 1e-3, a rest
//     fraction 0.01.
//
// Counts (landings, steps) and settings compare exactly. Timings are never
// results: wall-time ratios within 1.25 either way are timing noise on a
// shared machine.
#pragma once

#include <string>
#include <vector>

#include "report/metrics.hpp"
#include "report/run_data.hpp"

namespace elbowsim::report {

constexpr double kRelativeFloor = 0.01;  // of the quantity's scale
constexpr double kEnergyFloor = 1e-3;    // of the energy that flowed
constexpr double kStepFloorFactor = 2;   // x the change at half the step
constexpr double kTimingNoise = 1.25;    // wall-time ratio taken as noise

enum class MetricKind { result, numerics, timing, setting };
const char* to_string(MetricKind kind);  // "result", "numerics", "timing", "setting"

MetricKind metric_kind(const std::string& path);

struct NoiseFloor {
  double value = 0;   // in the metric's unit; differences at or below it are the same
  std::string basis;  // how it was set, for the report ("1 % of the energy that flowed, 15.8 J")
};

// The floor of metric `path` for these runs; per_run[r] is run r's metrics
// (run_metrics), runs[r] its folder's data (summary.json: scale, step_check).
NoiseFloor noise_floor(const std::string& path, const std::vector<RunData>& runs,
                       const std::vector<std::vector<Metric>>& per_run);

// Whether every run's value is within the floor of the first run's (for a
// timing: within kTimingNoise as a ratio; a setting or count: exactly equal).
// Nulls compare equal only to nulls.
bool same_within(const std::vector<nlohmann::ordered_json>& values, MetricKind kind,
                 const NoiseFloor& floor, const std::string& path);

}  // namespace elbowsim::report

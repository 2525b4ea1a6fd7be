// The metrics of a run, computed from its recording alone, so that
// summary.json, comparisons, sweeps and reports all quote the same numbers
// under the same names (a report can recompute them from trajectory.csv).
//
// Integrals over time use the trapezoid rule over the recorded samples;
// RMS values are time-weighted, sqrt(integral y^2 dt / duration). A 0/1
// flag (resting) holds from its sample to the next.
//
// The vocabulary is ELBOWSIM_METRICS below: each metric once, with its unit,
// its shape (one value; one per joint, per elbow or per contact body) and
// what it is. The names are constants (metric::hand_error_rms) for the code
// that computes, writes and reads them; summary.json writes them under
// "metrics." (report/summary_keys.hpp) with these units.
//
// The contact bodies (shape "body") are everything of the arm that can touch
// the table: each declared elbow (by name), then each link with a solid of its
// own ("link<j>"; a link without one records no finite distance and is left
// out), so that a forearm lying on the table is reported like an elbow.
#pragma once

#include <string>
#include <vector>

#include "engine/recording/recording.hpp"

// X(name, unit, shape, what): unit "" for a ratio or a count.
#define ELBOWSIM_METRICS(X)                                                                       \
  X(samples, "", one, "recorded rows")                                                            \
  X(hand_error_rms, "m", one, "RMS distance hand - desired hand (a task)")                        \
  X(hand_error_max, "m", one, "largest distance (a task)")                                        \
  X(hand_error_final, "m", one, "distance at the last sample (a task)")                           \
  X(hand_path_length, "m", one, "length of the hand's recorded path")                             \
  X(energy_in, "J", one, "electrical energy in (E_in at the end)")                                \
  X(joule, "J", one, "Joule loss (E_joule at the end)")                                           \
  X(energy_drawn, "J", one, "drawn from the supply (E_drawn at the end; motors)")                 \
  X(energy_regenerated, "J", one, "fed back by braking motors (E_regenerated; motors)")           \
  X(power_peak, "W", one, "largest sum_j v_j i_j (motors)")                                       \
  X(energy_in_per_joint, "J", per_joint, "integral of v_j i_j (motors)")                          \
  X(current_peak, "A", per_joint, "largest |i_j| (motors)")                                       \
  X(current_rms, "A", per_joint, "RMS of i_j (motors)")                                           \
  X(elbow_force_mean, "N", one, "mean normal force of all resting elbows' samples (contact)")     \
  X(elbow_force_min, "N", one, "smallest of them (0 when none rests)")                            \
  X(elbow_force_max, "N", one, "largest of them")                                                 \
  X(time_in_contact, "s", one, "time some elbow rests (contact)")                                 \
  X(rest_fraction, "", per_elbow, "share of the run the elbow rests (contact)")                   \
  X(elbow_force_peak, "N", per_elbow, "largest normal force on the elbow (contact)")              \
  X(elbow_drift_max, "m", per_elbow, "largest |d| (signed distance) while it rests (contact)")    \
  X(body_rest_fraction, "", per_body, "share of the run the body rests on the table (contact)")   \
  X(body_force_mean, "N", per_body, "its normal force averaged over its resting time (0: never)") \
  X(body_force_peak, "N", per_body, "its largest normal force")                                   \
  X(body_friction_work, "J", per_body, "friction's loss at it (E_friction_<body> at the end)")

namespace elbowsim {

// The metrics' names: metric::hand_error_rms is "hand_error_rms".
namespace metric {
#define ELBOWSIM_METRIC_NAME(name, unit, shape, what) inline constexpr char name[] = #name;
ELBOWSIM_METRICS(ELBOWSIM_METRIC_NAME)
#undef ELBOWSIM_METRIC_NAME
}  // namespace metric

struct Metric {
  enum class Shape { one, per_joint, per_elbow, per_body };
  std::string name;            // from the vocabulary (ELBOWSIM_METRICS)
  std::string unit;            // "m", "J", ...; "" for ratios and counts
  Shape shape = Shape::one;
  std::vector<double> values;  // 1, dof, elbows or bodies values
};

struct Metrics {
  std::vector<Metric> list;          // in vocabulary order; absent ones left out
  std::vector<std::string> elbows;   // the names behind per_elbow values
  std::vector<std::string> bodies;   // the names behind per_body values: elbows, then link<j>
  std::vector<int> body_links;       // [bodies] the link of a link body; -1 for an elbow

  const Metric* find(const std::string& name) const;  // nullptr when absent
  // The value of a one-value metric; throws std::out_of_range when absent.
  double operator[](const std::string& name) const;
};

Metrics compute_metrics(const Recording& recording);

// The unit of a metric of the vocabulary, "" for an unknown name and for a ratio or count.
std::string metric_unit(const std::string& name);
// Whether `name` is a metric of the vocabulary.
bool is_metric(const std::string& name);

}  // namespace elbowsim

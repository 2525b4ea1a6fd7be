// The metrics of a run, computed from its recording alone, so that
// summary.json, comparisons, sweeps and reports all quote the same numbers
// under the same names (a report can recompute them from trajectory.csv).
//
// Integrals over time use the trapezoid rule over the recorded samples;
// RMS values are time-weighted, sqrt(integral y^2 dt / duration). A 0/1
// flag (resting) holds from its sample to the next.
//
// The vocabulary (shape: one value, one per joint j, one per elbow e):
//   name                 unit  shape   what
//   samples              -     one     recorded rows
//   hand_error_rms       m     one     RMS distance hand - desired hand (a task)
//   hand_error_max       m     one     largest distance (a task)
//   hand_error_final     m     one     distance at the last sample (a task)
//   hand_path_length     m     one     length of the hand's recorded path
//   energy_in            J     one     electrical energy in (E_in at the end)
//   joule                J     one     Joule loss (E_joule at the end)
//   energy_drawn         J     one     drawn from the supply (E_drawn at the end; motors)
//   energy_regenerated   J     one     fed back by braking motors (E_regenerated; motors)
//   power_peak           W     one     largest sum_j v_j i_j (motors)
//   energy_in_per_joint  J     joint   integral of v_j i_j (motors)
//   current_peak         A     joint   largest |i_j| (motors)
//   current_rms          A     joint   RMS of i_j (motors)
//   elbow_force_mean     N     one     mean normal force over resting samples of all elbows (contact)
//   elbow_force_min      N     one     smallest of them (0 when none rests)
//   elbow_force_max      N     one     largest of them
//   time_in_contact      s     one     time some elbow rests (contact)
//   rest_fraction        -     elbow   share of the run the elbow rests (contact)
//   elbow_force_peak     N     elbow   largest normal force on the elbow (contact)
//   elbow_drift_max      m     elbow   largest |d| (signed distance) while it rests (contact)
//   body_rest_fraction   -     body    share of the run the body rests on the table (contact)
//   body_force_mean      N     body    its normal force averaged over the time it rests (0: never)
//   body_force_peak      N     body    its largest normal force
//   body_friction_work   J     body    energy friction took at it (E_friction_<body> at the end)
//
// The contact bodies (shape "body") are everything of the arm that can touch
// the table: each declared elbow (by name), then each link with a solid of its
// own ("link<j>"; a link without one records no finite distance and is left
// out), so that a forearm lying on the table is reported like an elbow.
#pragma once

#include <string>
#include <vector>

#include "engine/recording/recording.hpp"

namespace elbowsim {

struct Metric {
  enum class Shape { one, per_joint, per_elbow, per_body };
  std::string name;            // from the vocabulary above
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

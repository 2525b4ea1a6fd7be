// Per-run metrics of the experiment (hand accuracy, energy, currents, elbow
// forces), computed from the recording so they equal what the CSV holds.
#pragma once

#include <Eigen/Core>

#include "engine/model.hpp"

namespace elbowsim {

struct Recording;

struct Metrics {
  bool has_task = false;
  double hand_error_rms = 0, hand_error_max = 0, hand_error_final = 0;  // [m]
  double energy_in = 0, joule = 0;                                      // [J]
  Eigen::VectorXd energy_in_per_joint;        // [J] integral of v_j i_j (motors)
  Eigen::VectorXd current_peak, current_rms;  // [A] per joint (motors)
  bool has_contact = false;
  double elbow_force_mean = 0, elbow_force_min = 0, elbow_force_max = 0;  // [N] resting samples
  double time_in_contact = 0;  // [s] some elbow resting
};

// Time integrals by the trapezoid rule over the recorded samples (exact up
// to the recording interval); RMS values are time-weighted the same way.
Metrics compute_metrics(const Model& model, const Recording& recording);

}  // namespace elbowsim

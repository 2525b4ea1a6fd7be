// Impacts: a landing elbow with approach speed gets an impulse. All elbows
// that land together, and those already resting, are solved jointly:
//   u+ = u- + A P,  A = Jc (M + Jm)^-1 Jc^T,  P >= 0,
//   w = u+ + e u-(landing rows) >= 0,  P . w = 0     (Newton restitution e)
// and qd+ = qd- + (M + Jm)^-1 Jc^T P. Frictionless impulses.
#pragma once

#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

struct ImpactResult {
  std::vector<int> elbows;        // rows: landing elbows first, then resting ones
  Eigen::VectorXd impulse;        // [N s] per row
  Eigen::VectorXd speed_before;   // [m/s] normal velocity per row (< 0 approaching)
  Eigen::VectorXd speed_after;    // [m/s]
  Eigen::VectorXd energy_lost;    // [J] per row: -P_k (u-_k + u+_k) / 2; they sum to the loss
  double kinetic_before = 0, kinetic_after = 0;  // [J] 1/2 qd^T (M + Jm) qd
  bool solved = false;
};

// Applies the impulse to the rates in data.x. Needs forward_kinematics at
// the state's q and data.contact.normal for every elbow involved.
ImpactResult apply_impact(const Model& model, Data& data, const std::vector<int>& landing,
                          const std::vector<int>& resting);

}  // namespace elbowsim

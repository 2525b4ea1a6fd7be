// Rows against joints: whether the joints the task's elbows leave free can
// still move the hand in every direction it moves in. The inverse kinematics
// (inverse_kinematics.hpp) holds each kept elbow on its table plane (one row)
// or, when it sticks under Coulomb friction, at its point (three rows, fewer
// independent ones on a planar arm); the hand's target takes the rest. With
// too few joints left the plan can only miss its target, by a residual that
// says nothing of the cause; this counts it at a pose instead.
//
//   elbow_rank = rank(J_rows),  hand_free = rank([J_rows; J_hand]) - elbow_rank
//
// and the task fits when hand_free >= rank(J_hand): the elbows take none of
// the hand's directions. Ranks are numerical (numerical_rank: singular values
// above 1e-9 of the largest) and generic: the largest over the pose given and
// two poses near it (each joint moved by up to 0.3 rad), so that a singular
// start (an arm laid straight) is not mistaken for a missing joint.
#pragma once

#include <vector>

#include "engine/control/experiment.hpp"
#include "engine/data.hpp"

namespace elbowsim {

struct TaskFreedom {
  int joints = 0;                 // the arm's
  bool sticks = false;            // kept elbows held at a point (Coulomb friction), else on a plane
  std::vector<int> elbows;        // the kept elbows (model indices)
  int elbow_rank = 0;             // independent rows of the kept elbows at q
  int hand_rank = 0;              // directions the hand moves in at q (all joints free)
  int hand_free = 0;              // directions it moves in with the elbows' rows held
  bool fits() const { return hand_free >= hand_rank; }
};

// Near joint angles q [rad]: the task's kept elbows (experiment.task.elbows:
// on the table, or held at its clearance above it) and the hand.
TaskFreedom task_freedom(const Model& model, const Experiment& experiment, const Eigen::VectorXd& q);

// Per joint, at joint angles q: whether the task's resting elbows (kept on
// the table: clearance 0, contact on) hold it, i.e. it cannot move while
// they stay where they are (sticking under Coulomb friction: at their point;
// else on the table's plane). None when the task keeps no elbow on the table.
std::vector<bool> joints_held_by_table(const Model& model, const Experiment& experiment,
                                       const Eigen::VectorXd& q);

}  // namespace elbowsim

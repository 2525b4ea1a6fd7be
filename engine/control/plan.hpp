// The plan: the hand task turned into desired joint motion (by constrained
// inverse kinematics) and the feed-forward voltages that produce it,
// sampled on the simulation's step before the run starts.
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "engine/control/experiment.hpp"
#include "engine/control/inverse_kinematics.hpp"
#include "engine/data.hpp"

namespace elbowsim {

struct Plan {
  double dt = 0;                        // [s] sample spacing
  std::vector<Eigen::VectorXd> q, qd, qdd;  // [samples][n] desired joint motion
  std::vector<Eigen::Vector3d> hand;    // [samples] desired hand position [m]
  std::vector<Eigen::VectorXd> v_ff;    // [samples][n] feed-forward voltage [V] (pd_feedforward, force)
  std::vector<Eigen::VectorXd> f_ff;    // [samples][p] elbow forces the feed-forward assumes [N]
  std::vector<int> resting;             // elbows the plan keeps on the table (clearance 0, contact on)
  std::vector<int> held;                // elbows the plan holds above the table (clearance > 0)
  std::vector<std::string> warnings;    // about the plan (a near-singular pose), for the run's warnings
  std::vector<FailureCause> causes;     // what of them may explain a failure (step_log.hpp)

  // The desired hand position at time t, linear between samples (clamped to the ends).
  Eigen::Vector3d hand_at(double t) const {
    const double u = std::clamp(t / dt, 0.0, double(hand.size() - 1));
    const std::size_t k = std::min(std::size_t(u), hand.size() - 1);
    const std::size_t k1 = std::min(k + 1, hand.size() - 1);
    return hand[k] + (u - double(k)) * (hand[k1] - hand[k]);
  }

  // Linear interpolation of sampled vectors at time t (clamped to the
  // ends) into `out`, which has the right size: allocates nothing.
  void at(const std::vector<Eigen::VectorXd>& samples, double t, Eigen::Ref<Eigen::VectorXd> out) const {
    if (samples.size() == 1) {
      out = samples[0];
      return;
    }
    const double u = std::clamp(t / dt, 0.0, double(samples.size() - 1));
    const std::size_t k = std::min(std::size_t(u), samples.size() - 2);
    const double w = u - double(k);
    out = (1 - w) * samples[k] + w * samples[k + 1];
  }
};

// Builds the plan for the experiment's task over the model's duration, from
// the model (the controller's knowledge of the plant). Throws PlanError
// ("hand target ... at t = 1.25 s is out of reach: missed by 0.031 m") when
// the task cannot be followed.
std::shared_ptr<const Plan> make_plan(const Model& model, const Experiment& experiment);

// The task's first pose on `model`: initial.q moved by the inverse kinematics
// onto the hand's start and the task's elbow constraints (an elbow held
// above the table is lifted), as the plan's first sample. Throws PlanError.
Eigen::VectorXd start_pose(const Model& model, const Experiment& experiment);

// The controller a run on `plant` uses: the experiment's gains (or, with
// controller.tuning, the gains its rule places at the plan's first pose on
// the believed model: tuning.hpp) and, when it needs one, its plan, made from what the controller believes
// (experiment.believed(plant); throws PlanError). Null for an open-loop
// scene. The plant starts at the task's first pose solved on its own model
// (Controller::plant_start), not the plan's: a controller that believes the
// table lower would otherwise start the arm inside the real one.
std::shared_ptr<const Controller> make_controller(const Model& plant, const Experiment& experiment);

// The experiment's controller spec with its tuning rule's gains placed at
// the task's first pose on `model`, for what is judged before a run (the
// fixed step's stability under continuous control). Unchanged without a
// rule, or when the task cannot start (the run then names its plan error).
ControllerSpec gains_before_run(const Model& model, const Experiment& experiment);

}  // namespace elbowsim

// Controllers that turn the plan (desired joint motion) into motor voltages,
// saturated at the motor limit by the motor stage.
#pragma once

#include <Eigen/Core>

namespace elbowsim {

struct ControllerSpec {
  enum class Kind {
    open_loop,      // the scene's input profiles (no plan needed)
    pd,             // v = Kp (q_d - q) + Kd (qd_d - qd)
    pd_feedforward, // + v_ff: inverse dynamics of the plan through the motor model,
                    //   with the table carrying the support force that minimises |tau|
    force,          // + v_ff with the elbow force commanded: tau = M qdd_d + B - Jc^T f_d
  };
  Kind kind = Kind::open_loop;
  Eigen::VectorXd kp;             // [V/rad] per joint
  Eigen::VectorXd kd;             // [V s/rad] per joint
  double desired_force = 5.0;     // [N] per resting elbow (force control)
};

const char* to_string(ControllerSpec::Kind k);

// Constant load at the hand: a point mass carried at the hand point and/or a
// constant world force on it (e.g. pressing a pen).
struct HandLoad {
  double mass = 0.0;                                  // [kg] >= 0
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // [N] world
};

}  // namespace elbowsim

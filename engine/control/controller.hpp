// The control law: what voltage (or torque) each motor is commanded at time t
// for the state (q, qd). Open loop it plays the scene's input profiles
// (Model::inputs); a tracking controller follows the plan (plan.hpp) it was
// built with. The motor model (dynamics/motor.hpp) then saturates the command
// and turns it into current and torque; the plant never reads the controller.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "engine/control/digital_loop.hpp"
#include "engine/control/tuning.hpp"
#include "engine/data.hpp"

namespace elbowsim {

struct ControllerSpec {
  enum class Kind {
    open_loop,      // the scene's input profiles (no plan needed)
    pd,             // v = Kp (q_d - q) + Kd (qd_d - qd) [+ Ki int(q_d - q), sampled loops]
    pd_feedforward, // + v_ff: inverse dynamics of the plan through the motor model,
                    //   with the table carrying the support force that minimises |tau|
    force,          // + v_ff with the elbow force commanded: tau = M qdd_d + B - Jc^T f_d
  };
  Kind kind = Kind::open_loop;
  Eigen::VectorXd kp;             // [V/rad] per joint
  Eigen::VectorXd kd;             // [V s/rad] per joint
  // [V/(rad s)] per joint, or empty: integral action, in a sampled loop only
  // (the integral is the loop's state, digital_loop.hpp); 0 or empty: none.
  // make_controller leaves none on joints the resting elbows hold.
  Eigen::VectorXd ki;
  // When given, make_controller places kp, kd and ki by this rule on the
  // controller's model at the task's first pose (tuning.hpp).
  TuningRule tuning;
  double desired_force = 5.0;     // [N] per resting elbow (force control)
  DigitalLoopSpec loop;           // sampling, sensors, amplifier (digital_loop.hpp); default: continuous

  bool integral() const { return ki.size() > 0 && (ki.array() != 0).any(); }
};

const char* to_string(ControllerSpec::Kind k);

struct Plan;

// A tracking controller as a run uses it: its gains and the plan it follows.
// Built once before the run (make_controller in plan.hpp), shared read-only.
struct Controller {
  ControllerSpec spec;
  std::shared_ptr<const Plan> plan;
  // Where the plant starts (q): the task's first pose on the plant's own
  // model; empty: the plan's first pose (the controller knows the plant).
  Eigen::VectorXd plant_start;
  // With spec.tuning: the joint inertias I_j the rule placed the gains on
  // [kg m^2], and what the run should know about them (a Kd clamped at 0).
  Eigen::VectorXd tuning_inertia;
  std::vector<std::string> warnings;
  // Joints whose integral gain make_controller set to 0: the task's resting
  // elbows hold them (task_freedom.hpp, joints_held_by_table).
  std::vector<int> integral_held;
};

// The command at time t for the state (q [n], qd [n]): with a motor, the
// unsaturated voltage into data.voltage [V]; without one, the joint torque
// into data.actuation [N m]. Tracking controllers also leave the plan's
// q_desired, qd_desired (and v_feedforward) at t in data. Allocates nothing.
// Sampled control (spec.loop.sampled()): the voltage the amplifier holds
// (digital_loop.hpp), whatever t, q and qd.
void command(const Model& model, Data& data, double t, ConstVec q, ConstVec qd);

// The control law itself on the state (q, qd) it is given (true or
// measured): the unsaturated voltage into data.voltage. A tracking
// controller also leaves the plan at t in data. Allocates nothing.
void control_law(const Model& model, Data& data, double t, ConstVec q, ConstVec qd);

}  // namespace elbowsim

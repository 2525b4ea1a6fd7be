// Hand tasks: where the hand should be over time (issue: the paper's
// experiment). A path in space with a smooth time scaling, after a delay.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace elbowsim {

struct HandTask {
  enum class Path { none, hold, line, circle, waypoints };
  enum class Timing { quintic, minimum_jerk };
  Path path = Path::none;
  Timing timing = Timing::quintic;  // s(tau), tau = (t - start_delay) / duration in [0, 1]
  double start_delay = 0.0;         // [s] hold the start point this long
  double duration = 1.0;            // [s] > 0, time to traverse the path
  // line: points[0] -> points[1]; waypoints: through all points (a natural
  // cubic spline on chord-length knots, C2; consecutive points differ); hold: points[0]. A non-finite (NaN) points[0], or no
  // points, means the hand's position at the initial pose.
  std::vector<Eigen::Vector3d> points;  // [m] world (offsets with from_start)
  // circle: centre, radius, plane normal, start angle; one full turn.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // [m]
  double radius = 0.05;                              // [m]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY(); // circle plane normal
  double start_angle = 0.0;                          // [rad]
  // Points and centre are offsets from the hand's start (task.origin: start),
  // so one task fits every initial pose; else world positions.
  bool from_start = false;

  // Elbows the inverse kinematics keeps on the table (clearance 0) or the
  // stated clearance above it (the elbow-off variant). Names from Model::elbows.
  std::vector<std::string> elbows;
  double elbow_clearance = 0.0;  // [m] >= 0

  Eigen::VectorXd posture;        // [dof] preferred joints for the redundancy; empty = initial q
  // [s] spacing of the plan's samples (IK, feed-forward); 0: simulation.step.
  // Part of the experiment: studies that change the integration step pin it
  // (elbowsim accuracy, --check-step, the Monte Carlo floor), so that they
  // measure integration error, not a finer plan.
  double plan_step = 0.0;
  double posture_weight = 0.1;    // null-space gain per IK iteration: 1 = the solution closest
                                  // to the posture (it can jump branch near full stretch);
                                  // < 1 drifts toward it over samples, continuously
  Eigen::VectorXd q_min, q_max;   // [dof] joint limits [rad]; empty = none
};

struct HandTarget {
  Eigen::Vector3d p, v, a;  // [m], [m/s], [m/s^2] world
};

// Position, velocity and acceleration of the desired hand point at time t.
// `start` replaces an empty first point (the hand at the initial pose).
HandTarget hand_target(const HandTask& task, const Eigen::Vector3d& start, double t);

// Smooth time scaling s(tau), s'(tau), s''(tau) on [0, 1] (clamped outside).
Eigen::Vector3d time_scaling(HandTask::Timing timing, double tau);

}  // namespace elbowsim

#include "support/experiment_scenes.hpp"

#include <cmath>

#include "engine/dynamics/kinematics.hpp"

namespace elbowsim::testing {

ExperimentScene WritingArm::scene() const {
  ExperimentScene scene;
  Model& m = scene.model;
  Experiment& x = scene.experiment;
  m = planar_arm({{0.25, 1.2, 0.125, 0.00625}, {0.25, 1.0, 0.125, 0.0052},
                        {0.2, 0.6, 0.1, 0.002}, {0.15, 0.4, 0.075, 0.00075}});
  const Eigen::Vector4d q0(0.6, -1.3, 0.9, 0.4);
  const double elbow_z = 0.25 * std::sin(0.6) + 0.25 * std::sin(-0.7);
  m.elbows = {Elbow{"elbow", 1, Eigen::Vector3d(0.25, 0, 0), 0.03}};
  TableBox table;
  table.size = Eigen::Vector3d(0.7, 0.6, 0.1);
  table.center = Eigen::Vector3d(0.65, 0, elbow_z - 0.03 - 0.05);
  m.table = {table};
  m.effects.motor = MotorModel::full;
  m.effects.damping = true;
  m.effects.contact = true;  // the table is solid for both: elbow off means held 2 cm above it
  Motor servo = small_servo();
  servo.gear_ratio = 100;
  m.motors.assign(4, servo);
  m.damping = Eigen::Vector4d::Constant(0.05);
  m.initial.q = q0;
  x.task.path = path;
  x.task.duration = task_duration;
  x.task.start_delay = 0.2;
  x.task.points = {Eigen::Vector3d::Constant(NAN), Eigen::Vector3d::Constant(NAN)};
  x.task.elbows = {"elbow"};
  x.task.elbow_clearance = elbow_on ? 0.0 : 0.02;
  x.controller.kind = controller;
  x.controller.kp = Eigen::Vector4d::Constant(50.0);
  x.controller.kd = Eigen::Vector4d::Constant(2.0);
  m.options = {run_duration, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  // The line: 6 cm forward and 2 cm up from where the hand starts.
  Data data(m);
  forward_kinematics(m, data, q0);
  const Eigen::Vector3d hand = point_position(data, m.hand_link, m.hand_point);
  x.task.points = {hand, hand + Eigen::Vector3d(0.06, 0, 0.02)};
  if (path == HandTask::Path::hold) x.task.points = {hand};
  return scene;
}

}  // namespace elbowsim::testing

// engine/dynamics/applied_torques.cpp: the torques besides gravity, bias and
// damping: the hand force acts as J^T F with power F . v_hand, and sliding
// joints add their dry friction to tau_applied (stuck ones nothing).
#include <doctest/doctest.h>

#include "engine/dynamics/applied_torques.hpp"
#include "engine/dynamics/joint_friction.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/models.hpp"

using namespace elbowsim;

TEST_CASE("applied_torques: J^T F of the hand force and its power; sliding friction into tau_applied") {
  Model m = testing::planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.2, 0.5, 0.1, 0.005}});
  m.effects.motor = MotorModel::none;
  m.hand_load.force = Eigen::Vector3d(2.0, 0.0, -3.0);
  m.effects.joint_friction = true;
  m.joint_friction = {{0.2, 0.5, 0.01}, {0.1, 0.1, 0.01}};
  finalize(m);
  Data data(m);
  const Eigen::Vector2d q(0.3, -0.5), qd(0.4, 0.0);
  forward_kinematics(m, data, q);
  Eigen::MatrixXd J(3, 2);
  point_jacobian(m, data, m.hand_link, m.hand_point, J);
  data.actuation = Eigen::Vector2d(1.0, 0.2);
  data.joint_mode = {1, 0};  // joint 0 slides forward, joint 1 stuck
  const double power = applied_torques(m, data, qd);
  const Eigen::Vector2d expected_actuation = Eigen::Vector2d(1.0, 0.2) + J.transpose() * m.hand_load.force;
  CHECK(data.actuation.isApprox(expected_actuation, 1e-15));
  CHECK(power == doctest::Approx(m.hand_load.force.dot(J * qd)).epsilon(1e-15));
  CHECK(data.joint_friction_torque[0] == -sliding_friction(m.joint_friction[0], 0.4));
  CHECK(data.joint_friction_torque[1] == 0.0);
  CHECK(data.tau_applied.isApprox(expected_actuation + data.joint_friction_torque, 1e-15));

  // No hand force and no joint friction: tau_applied is the actuation, power 0.
  Model plain = testing::planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.2, 0.5, 0.1, 0.005}});
  plain.effects.motor = MotorModel::none;
  finalize(plain);
  Data d(plain);
  forward_kinematics(plain, d, q);
  d.actuation = Eigen::Vector2d(1.0, 0.2);
  CHECK(applied_torques(plain, d, qd) == 0.0);
  CHECK(d.actuation == Eigen::Vector2d(1.0, 0.2));
  CHECK(d.tau_applied == d.actuation);
}

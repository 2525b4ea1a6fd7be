// engine/dynamics/joint_friction.cpp: the Stribeck curve, and the dynamics in
// given modes: a sliding joint is resisted against its motion, a stuck one is
// locked and its holding torque is what balances the rest.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/dynamics/joint_friction.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

// Two links in a vertical plane under gravity, no motor: torques are inputs.
Model two_links() {
  Model m = testing::planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.2, 0.5, 0.1, 0.005}});
  m.effects.motor = MotorModel::none;
  m.effects.joint_friction = true;
  m.joint_friction = {{0.2, 0.5, 0.01}, {0.1, 0.1, 0.01}};
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("sliding_friction: breakaway at rest, Coulomb at speed, the Stribeck curve between") {
  const JointFriction f{0.2, 0.5, 0.01};
  CHECK(sliding_friction(f, 0.0) == 0.5);
  CHECK(sliding_friction(f, 0.01) == doctest::Approx(0.2 + 0.3 * std::exp(-1.0)).epsilon(1e-15));
  CHECK(sliding_friction(f, 1.0) == doctest::Approx(0.2).epsilon(1e-15));
}

TEST_CASE("joint_friction_dynamics: sliding torques oppose the modes; a stuck joint has qdd 0 and holds the rest") {
  const Model m = two_links();
  Data data(m);
  const Eigen::Vector2d q(0.3, -0.5), qd(0.4, -2.0);
  forward_kinematics(m, data, q);
  data.actuation = Eigen::Vector2d(1.0, 0.2);
  // Both sliding: forward dynamics with the friction torques added.
  data.joint_mode = {1, -1};
  sliding_friction_torques(m, data, qd);
  CHECK(data.tau_applied == data.actuation + data.joint_friction_torque);
  joint_friction_dynamics(m, data, qd);
  const Eigen::Vector2d friction(-sliding_friction(m.joint_friction[0], 0.4), +0.1);
  CHECK(data.joint_friction_torque.isApprox(friction, 1e-15));
  Eigen::VectorXd expected(2);
  forward_dynamics(m, data, qd, data.actuation + friction, expected);
  CHECK(data.qdd.isApprox(expected, 1e-13));
  // Joint 0 stuck: qdd_0 = 0 exactly, joint 1 moves as if joint 0 were
  // welded, and M qdd = tau - B + friction holds in both rows.
  data.joint_mode = {0, -1};
  const Eigen::Vector2d rest(0.0, -2.0);
  sliding_friction_torques(m, data, rest);
  CHECK(data.joint_friction_torque[0] == 0.0);  // stuck: held, not yet known
  joint_friction_dynamics(m, data, rest);
  CHECK(data.qdd[0] == 0.0);
  const Eigen::VectorXd residual =
      data.mass_matrix * data.qdd - (data.actuation + data.joint_friction_torque - data.bias);
  CHECK(residual.norm() < 1e-12);
  CHECK(data.joint_friction_torque[1] == 0.1);  // sliding negative: friction positive
}

// engine/dynamics/aba.cpp: the articulated-body algorithm on its own.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::random_chain;

TEST_CASE("aba honours effects: no gravity, no armature, no damping") {
  Model model = random_chain(5, 42);
  model.effects.gravity = false;
  model.effects.damping = false;
  model.effects.rotor_inertia = false;
  finalize(model);
  Data data(model);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(5), qd = Eigen::VectorXd::Random(5);
  const Eigen::VectorXd tau = Eigen::VectorXd::Random(5);
  forward_kinematics(model, data, q);
  Eigen::VectorXd qdd_aba(5), qdd_crba(5);
  forward_dynamics(model, data, DynamicsMethod::aba, qd, tau, qdd_aba);
  forward_dynamics(model, data, DynamicsMethod::crba, qd, tau, qdd_crba);
  CHECK(approx(qdd_aba, qdd_crba, 1e-10, 1e-10));
  CHECK(model.armature.isZero());
  CHECK(model.viscous.isZero());
}

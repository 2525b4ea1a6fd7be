// engine/dynamics/aba.cpp: the articulated-body algorithm on its own.
#include <doctest/doctest.h>

#include <cmath>

#include <Eigen/Cholesky>
#include <algorithm>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
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

TEST_CASE("aba(q, qd, M a + b) == a on random chains of 1-12 joints, tau from RNEA, directly") {
  // M a + b is computed by Newton-Euler (inverse_dynamics with every term), an
  // algorithm ABA shares nothing with; armature Jm, damping and gravity are on.
  // Rounding grows with n and the spread of inertias: 1e-9 absolute + relative.
  for (int n = 1; n <= 12; ++n) {
    CAPTURE(n);
    const Model model = random_chain(n, 600 + n);
    REQUIRE(model.has_armature());
    Data data(model);
    const Eigen::VectorXd q = 3.0 * Eigen::VectorXd::Random(n);
    const Eigen::VectorXd qd = 2.0 * Eigen::VectorXd::Random(n);
    const Eigen::VectorXd a = 4.0 * Eigen::VectorXd::Random(n);
    forward_kinematics(model, data, q);
    Eigen::VectorXd tau(n), qdd(n);
    inverse_dynamics(model, data, qd, a, InverseDynamicsTerms{}, tau);
    forward_dynamics_aba(model, data, qd, tau, qdd);
    CHECK(approx(qdd, a, 1e-9, 1e-9));
  }
}

TEST_CASE("aba: a single-link pendulum gets qdd = (tau - m g lc cos q - D qd) / (I + m lc^2)") {
  // Planar link (axis -y, angle from +x toward +z), com lc along it, inertia I about
  // the com: the textbook equation of a pendulum with a viscous joint.
  const double l = 0.5, m = 1.3, lc = 0.2, I = 0.021, D = 0.07, g = 9.81;
  Model model = elbowsim::testing::planar_arm({{l, m, lc, I}});
  model.effects.damping = true;
  model.damping = Eigen::VectorXd::Constant(1, D);
  finalize(model);
  Data data(model);
  for (double q : {0.0, 0.4, -1.1}) {
    for (double qd : {0.0, 1.5}) {
      for (double tau : {0.0, 1.2}) {
        const Eigen::VectorXd qv = Eigen::VectorXd::Constant(1, q), qdv = Eigen::VectorXd::Constant(1, qd);
        forward_kinematics(model, data, qv);
        Eigen::VectorXd qdd(1);
        forward_dynamics_aba(model, data, qdv, Eigen::VectorXd::Constant(1, tau), qdd);
        const double expected = (tau - m * g * lc * std::cos(q) - D * qd) / (I + m * lc * lc);
        CAPTURE(q);
        CAPTURE(qd);
        CAPTURE(tau);
        CHECK(approx(qdd[0], expected, 1e-13, 1e-13));  // rounding on numbers of order 10
      }
    }
  }
}

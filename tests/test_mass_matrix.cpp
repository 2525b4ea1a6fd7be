// Walker-Orin (paper eq. 52-54), CRBA and ABA agree on random spatial chains.
#include <doctest/doctest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::random_chain;

TEST_CASE("mass matrix: Walker-Orin == CRBA (1e-10 relative), symmetric positive definite") {
  for (int n = 1; n <= 12; ++n) {
    CAPTURE(n);
    const Model model = random_chain(n, 100 + n);
    Data data(model);
    const Eigen::VectorXd q = 3.0 * Eigen::VectorXd::Random(n);
    forward_kinematics(model, data, q);
    mass_matrix_walker_orin(model, data);
    const Eigen::MatrixXd M_wo = data.mass_matrix;
    data.mass_matrix.setZero();
    mass_matrix_crba(model, data);
    const Eigen::MatrixXd M_crba = data.mass_matrix;
    const double scale = M_crba.cwiseAbs().maxCoeff();
    CHECK((M_wo - M_crba).cwiseAbs().maxCoeff() <= 1e-10 * scale);
    CHECK((M_crba - M_crba.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M_crba);
    CHECK(eig.eigenvalues().minCoeff() > 0);
  }
}

TEST_CASE("aba(q, qd, M a + bias) == a, and all three forward-dynamics methods agree") {
  for (int n = 1; n <= 12; ++n) {
    CAPTURE(n);
    const Model model = random_chain(n, 200 + n);
    Data data(model);
    const Eigen::VectorXd q = 3.0 * Eigen::VectorXd::Random(n);
    const Eigen::VectorXd qd = 2.0 * Eigen::VectorXd::Random(n);
    const Eigen::VectorXd a = 4.0 * Eigen::VectorXd::Random(n);
    forward_kinematics(model, data, q);
    mass_matrix_crba(model, data);
    bias_torques(model, data, qd);
    const Eigen::VectorXd tau = data.mass_matrix * a + data.bias;
    Eigen::VectorXd qdd(n);
    forward_dynamics_aba(model, data, qd, tau, qdd);
    CHECK(approx(qdd, a, 1e-9, 1e-9));
    for (DynamicsMethod method : {DynamicsMethod::walker_orin, DynamicsMethod::crba}) {
      forward_dynamics(model, data, method, qd, tau, qdd);
      CHECK(approx(qdd, a, 1e-9, 1e-9));
    }
  }
}

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

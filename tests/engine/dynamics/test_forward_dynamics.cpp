// engine/dynamics/forward_dynamics.cpp: qdd for applied torques by the method the
// scene selects (Walker-Orin, CRBA, ABA); the three agree.
#include <doctest/doctest.h>

#include <cstring>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::random_chain;

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

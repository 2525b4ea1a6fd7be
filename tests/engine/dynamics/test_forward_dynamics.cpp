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

TEST_CASE("forward_dynamics without a method runs model.options.dynamics, bit for bit") {
  for (DynamicsMethod method : {DynamicsMethod::walker_orin, DynamicsMethod::crba, DynamicsMethod::aba}) {
    CAPTURE(std::string(to_string(method)));
    Model model = random_chain(6, 71);
    model.options.dynamics = method;
    finalize(model);
    Data data(model);
    const Eigen::VectorXd q = Eigen::VectorXd::Random(6), qd = Eigen::VectorXd::Random(6);
    const Eigen::VectorXd tau = 3.0 * Eigen::VectorXd::Random(6);
    forward_kinematics(model, data, q);
    Eigen::VectorXd by_model(6), by_name(6);
    forward_dynamics(model, data, qd, tau, by_model);
    forward_dynamics(model, data, method, qd, tau, by_name);
    CHECK(std::memcmp(by_model.data(), by_name.data(), 6 * sizeof(double)) == 0);
  }
}

TEST_CASE("forward_dynamics: the three methods agree with each effect switched off in turn") {
  // Each method must drop the same terms: gravity, damping, rotor inertia, motors.
  // Rounding of two factorisations of M: 1e-10 absolute + relative.
  struct Case {
    const char* what;
    bool gravity, damping, rotor_inertia;
    MotorModel motor;
  };
  const Case cases[] = {{"all on", true, true, true, MotorModel::full},
                        {"no gravity", false, true, true, MotorModel::full},
                        {"no damping", true, false, true, MotorModel::full},
                        {"no rotor inertia", true, true, false, MotorModel::full},
                        {"quasi-static motors", true, true, true, MotorModel::quasi_static},
                        {"no motors", true, true, true, MotorModel::none}};
  for (const Case& c : cases) {
    CAPTURE(std::string(c.what));
    Model model = random_chain(5, 81);
    model.effects.gravity = c.gravity;
    model.effects.damping = c.damping;
    model.effects.rotor_inertia = c.rotor_inertia;
    model.effects.motor = c.motor;
    finalize(model);
    Data data(model);
    const Eigen::VectorXd q = 2.0 * Eigen::VectorXd::Random(5), qd = Eigen::VectorXd::Random(5);
    const Eigen::VectorXd tau = 2.0 * Eigen::VectorXd::Random(5);
    forward_kinematics(model, data, q);
    Eigen::VectorXd wo(5), crba(5), aba(5);
    forward_dynamics(model, data, DynamicsMethod::walker_orin, qd, tau, wo);
    forward_dynamics(model, data, DynamicsMethod::crba, qd, tau, crba);
    forward_dynamics(model, data, DynamicsMethod::aba, qd, tau, aba);
    CHECK(approx(crba, wo, 1e-10, 1e-10));
    CHECK(approx(aba, wo, 1e-10, 1e-10));
    // And the result is the inverse of RNEA with the same effects.
    Eigen::VectorXd back(5);
    inverse_dynamics(model, data, qd, aba, InverseDynamicsTerms{}, back);
    CHECK(approx(back, tau, 1e-10, 1e-10));
  }
}

TEST_CASE("forward_dynamics: holding torques tau = G(q) give qdd = 0 at rest, for every method") {
  // Statics: a chain at rest under exactly its gravity torques does not move.
  // 1e-10 rad/s^2 against gravity accelerations of order 10.
  const Model model = random_chain(7, 91);
  Data data(model);
  const Eigen::VectorXd q = 2.0 * Eigen::VectorXd::Random(7), rest = Eigen::VectorXd::Zero(7);
  forward_kinematics(model, data, q);
  Eigen::VectorXd G(7), qdd(7);
  inverse_dynamics(model, data, rest, rest, {false, true, false}, G);
  for (DynamicsMethod method : {DynamicsMethod::walker_orin, DynamicsMethod::crba, DynamicsMethod::aba}) {
    CAPTURE(std::string(to_string(method)));
    forward_dynamics(model, data, method, rest, G, qdd);
    CHECK(qdd.cwiseAbs().maxCoeff() < 1e-10);
    forward_dynamics(model, data, method, rest, Eigen::VectorXd::Zero(7), qdd);
    CHECK(qdd.cwiseAbs().maxCoeff() > 1.0);  // unheld, it falls
  }
}

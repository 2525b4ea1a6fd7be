// engine/dynamics/rnea.cpp: inverse dynamics against the textbook closed form of a 2-link planar arm.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"
#include "support/two_link_closed_form.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::TwoLinkClosedForm;

TEST_CASE("rnea: 2-link planar arm matches the closed-form M, Coriolis and gravity (1e-12)") {
  const TwoLinkClosedForm ref;
  const Model model = ref.model();
  Data data(model);
  std::srand(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector2d q = 3.0 * Eigen::Vector2d::Random();
    const Eigen::Vector2d qd = 2.0 * Eigen::Vector2d::Random();
    const Eigen::Vector2d qdd = 5.0 * Eigen::Vector2d::Random();
    forward_kinematics(model, data, q);
    Eigen::Vector2d tau;

    inverse_dynamics(model, data, qd, qdd, {false, false, false}, tau);
    CHECK(approx(tau, ref.M(q) * qdd, 1e-12));

    inverse_dynamics(model, data, qd, data.zero, {true, false, false}, tau);
    CHECK(approx(tau, ref.coriolis(q, qd), 1e-12));

    inverse_dynamics(model, data, data.zero, data.zero, {false, true, false}, tau);
    CHECK(approx(tau, ref.gravity(q), 1e-12));

    inverse_dynamics(model, data, qd, qdd, {}, tau);
    CHECK(approx(tau, ref.M(q) * qdd + ref.coriolis(q, qd) + ref.gravity(q), 1e-12));
  }
}

TEST_CASE("rnea: motor-reflected terms Jm qdd and (D + Dm) qd of eq. (51)") {
  const TwoLinkClosedForm ref;
  Model model = ref.model();
  model.effects.motor = MotorModel::full;
  model.effects.damping = true;
  model.effects.rotor_inertia = true;
  model.motors = {elbowsim::testing::small_servo(), elbowsim::testing::small_servo()};
  model.damping = Eigen::Vector2d(0.1, 0.2);
  finalize(model);
  Data data(model);
  const Eigen::Vector2d q(0.3, -0.7), qd(1.1, -0.4), qdd(2.0, 3.0);
  forward_kinematics(model, data, q);
  Eigen::Vector2d tau;
  inverse_dynamics(model, data, qd, qdd, {}, tau);
  const double k2 = 50.0 * 50.0;
  const Eigen::Vector2d jm = Eigen::Vector2d::Constant(5e-7 * k2);
  const Eigen::Vector2d visc = model.damping + Eigen::Vector2d::Constant(1e-6 * k2);
  const Eigen::Vector2d expected = ref.M(q) * qdd + ref.coriolis(q, qd) + ref.gravity(q) +
                                   jm.cwiseProduct(qdd) + visc.cwiseProduct(qd);
  CHECK(approx(tau, expected, 1e-12));
}

// Inverse dynamics against the textbook closed form of a 2-link planar arm.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;

namespace {

// Spong, Hutchinson & Vidyasagar, "Robot Modeling and Control", sec. 7.4.
// Angles from +x toward +z, gravity -z: heights are lc1 sin q1, etc.
struct TwoLinkClosedForm {
  double l1 = 0.4, lc1 = 0.17, lc2 = 0.21, m1 = 1.3, m2 = 0.8, I1 = 0.021, I2 = 0.013, g = 9.81;

  Eigen::Matrix2d M(const Eigen::Vector2d& q) const {
    const double c2 = std::cos(q[1]);
    Eigen::Matrix2d M;
    M(0, 0) = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2) + I1 + I2;
    M(0, 1) = M(1, 0) = m2 * (lc2 * lc2 + l1 * lc2 * c2) + I2;
    M(1, 1) = m2 * lc2 * lc2 + I2;
    return M;
  }
  Eigen::Vector2d coriolis(const Eigen::Vector2d& q, const Eigen::Vector2d& qd) const {
    const double h = -m2 * l1 * lc2 * std::sin(q[1]);
    return {h * (2 * qd[0] * qd[1] + qd[1] * qd[1]), -h * qd[0] * qd[0]};
  }
  Eigen::Vector2d gravity(const Eigen::Vector2d& q) const {
    const double c1 = std::cos(q[0]), c12 = std::cos(q[0] + q[1]);
    return {(m1 * lc1 + m2 * l1) * g * c1 + m2 * lc2 * g * c12, m2 * lc2 * g * c12};
  }
  Model model() const {
    return elbowsim::testing::planar_arm({{l1, m1, lc1, I1}, {0.3, m2, lc2, I2}});
  }
};

}  // namespace

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

// engine/dynamics/walker_orin.cpp: the paper's mass matrix (eq. 54, column i =
// INV(q, 0, e_i, 0)) and bias torques B_J = INV(q, qd, 0, g) (eq. 52) against the
// textbook closed form of a 2-link planar arm.
#include <doctest/doctest.h>

#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"
#include "support/two_link_closed_form.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::TwoLinkClosedForm;

TEST_CASE("walker-orin: M(q) and B_J(q, qd) of a 2-link arm == the closed form (1e-12)") {
  const TwoLinkClosedForm ref;
  const Model model = ref.model();
  Data data(model);
  std::srand(17);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector2d q = 3.0 * Eigen::Vector2d::Random(), qd = 2.0 * Eigen::Vector2d::Random();
    forward_kinematics(model, data, q);
    mass_matrix_walker_orin(model, data);
    bias_torques(model, data, qd);
    // Numbers of order 1 and a few dozen roundings: 1e-12 absolute, as in test_rnea.
    CHECK(approx(data.mass_matrix, ref.M(q), 1e-12));
    CHECK(approx(data.bias, Eigen::Vector2d(ref.coriolis(q, qd) + ref.gravity(q)), 1e-12));
  }
}

TEST_CASE("walker-orin: motor-reflected terms, M + Jm on the diagonal and (D + Dm) qd in B_J") {
  const TwoLinkClosedForm ref;
  Model model = ref.model();
  model.effects.motor = MotorModel::full;
  model.effects.damping = true;
  model.effects.rotor_inertia = true;
  model.motors = {elbowsim::testing::small_servo(), elbowsim::testing::small_servo()};
  model.damping = Eigen::Vector2d(0.1, 0.2);
  finalize(model);
  Data data(model);
  const Eigen::Vector2d q(0.3, -0.7), qd(1.1, -0.4);
  forward_kinematics(model, data, q);
  mass_matrix_walker_orin(model, data);
  bias_torques(model, data, qd);
  const double k2 = 50.0 * 50.0;  // small_servo: gear 50, Im 5e-7, dm 1e-6
  const Eigen::Matrix2d M = ref.M(q) + Eigen::Matrix2d(Eigen::Vector2d::Constant(5e-7 * k2).asDiagonal());
  const Eigen::Vector2d visc = model.damping + Eigen::Vector2d::Constant(1e-6 * k2);
  CHECK(approx(data.mass_matrix, M, 1e-12));
  CHECK(approx(data.bias, Eigen::Vector2d(ref.coriolis(q, qd) + ref.gravity(q) + visc.cwiseProduct(qd)), 1e-12));
  // Switched off, the effects leave no trace.
  model.effects.gravity = false;
  model.effects.damping = false;
  model.effects.rotor_inertia = false;
  finalize(model);
  Data plain(model);
  forward_kinematics(model, plain, q);
  mass_matrix_walker_orin(model, plain);
  bias_torques(model, plain, qd);
  CHECK(approx(plain.mass_matrix, ref.M(q), 1e-12));
  CHECK(approx(plain.bias, ref.coriolis(q, qd), 1e-12));
}

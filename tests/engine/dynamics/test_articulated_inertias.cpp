// engine/dynamics/articulated_inertias.cpp: ABA's inward pass on the upper
// 2 x 2 blocks of the symmetric articulated inertia, against the plain 6 x 6
// recursion of forward_dynamics_aba (aba.cpp).
#include <doctest/doctest.h>

#include <Eigen/Cholesky>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::random_chain;

TEST_CASE("articulated_inertias: U, D, U / D, 1 / D, S, coupling == the 6 x 6 recursion (1e-12)") {
  // The reference: forward_dynamics_aba's inward pass, full 6 x 6 matrices,
  // U_i = I^A_i S_i with I^A_i projected before the product. Chains with
  // armature, at random q (U and D do not depend on qd or tau).
  for (int n : {1, 2, 3, 7, 30}) {
    CAPTURE(n);
    const Model model = random_chain(n, static_cast<std::uint32_t>(300 + n));
    REQUIRE(model.has_armature());
    Data ref(model), data(model);
    const Eigen::VectorXd q = Eigen::VectorXd::Random(n);
    const Eigen::VectorXd qd = Eigen::VectorXd::Random(n), tau = Eigen::VectorXd::Random(n);
    Eigen::VectorXd qdd(n);
    forward_kinematics(model, ref, q);
    forward_dynamics_aba(model, ref, qd, tau, qdd);
    forward_kinematics(model, data, q);
    data.coupling.setConstant(7.0);  // every entry must be written
    articulated_inertias(model, data);
    for (int i = 0; i < n; ++i) {
      CAPTURE(i);
      const double scale = ref.U[i].cwiseAbs().maxCoeff();
      CHECK(approx(data.motion_subspace[i], ref.motion_subspace[i], 0.0));
      CHECK(approx(data.U[i], ref.U[i], 1e-12 * scale));
      CHECK(approx(data.D[i], ref.D[i], 1e-12 * ref.D[i]));
      CHECK(approx(data.D_inv[i], ref.D_inv[i], 1e-12 * ref.D_inv[i]));
      CHECK(approx(data.U_over_D[i], ref.U_over_D[i], 1e-12 * scale * ref.D_inv[i]));
      CHECK(approx(data.coupling[i], ref.coupling[i], 1e-12 * (1 + std::abs(ref.coupling[i]))));
    }
    CHECK(ref.coupling[n - 1] == 0.0);
    CHECK(data.coupling[n - 1] == 0.0);
  }
}

TEST_CASE("aba_response after forward_dynamics_aba (its U, D, coupling) == CRBA + Cholesky") {
  for (int n : {1, 2, 7, 30}) {
    CAPTURE(n);
    const Model model = random_chain(n, static_cast<std::uint32_t>(400 + n));
    Data data(model);
    forward_kinematics(model, data, Eigen::VectorXd::Random(n));
    Eigen::VectorXd qdd(n);
    forward_dynamics_aba(model, data, Eigen::VectorXd::Random(n), Eigen::VectorXd::Random(n), qdd);
    mass_matrix_crba(model, data);
    const Eigen::VectorXd tau = Eigen::VectorXd::Random(n);
    const Eigen::VectorXd expected = Eigen::LLT<Eigen::MatrixXd>(data.mass_matrix).solve(tau);
    Eigen::VectorXd x(n);
    aba_response(model, data, tau, x);
    CHECK(approx(x, expected, 1e-10 * expected.cwiseAbs().maxCoeff()));
  }
}

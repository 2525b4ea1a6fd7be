// engine/dynamics/aba_response.cpp: x = (M + Jm)^-1 tau from the articulated
// inertias, one column (aba_response) or a batch (aba_responses).
#include <doctest/doctest.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <vector>

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::random_chain;

TEST_CASE("aba_response: x = (M + Jm)^-1 tau from the articulated inertias, == CRBA + Cholesky (1e-10)") {
  // Chains of 1-30 joints with armature; tau dense, with trailing zeros (the inward
  // sweep starts at its last non-zero entry), and x aliasing tau.
  for (int n : {1, 2, 7, 30}) {
    CAPTURE(n);
    const Model model = random_chain(n, static_cast<std::uint32_t>(60 + n));
    REQUIRE(model.has_armature());
    Data data(model);
    forward_kinematics(model, data, Eigen::VectorXd::Random(n));
    mass_matrix_crba(model, data);
    articulated_inertias(model, data);
    const Eigen::LLT<Eigen::MatrixXd> llt(data.mass_matrix);
    for (int last = n - 1; last >= 0; last -= std::max(1, n / 3)) {
      CAPTURE(last);
      Eigen::VectorXd tau = Eigen::VectorXd::Zero(n);
      tau.head(last + 1).setRandom();
      const Eigen::VectorXd expected = llt.solve(tau);
      Eigen::VectorXd x(n);
      aba_response(model, data, tau, x);
      CHECK(approx(x, expected, 1e-10 * expected.cwiseAbs().maxCoeff()));
      aba_response(model, data, tau, tau);  // in place
      CHECK(approx(tau, x, 0.0));
    }
  }
}

TEST_CASE("aba_responses: m = 0..7 columns at once == aba_response per column (bit for bit)") {
  // Columns read with a stride (rows of a column-major m x n matrix, as the
  // contact rows are), with trailing zeros that differ per column, and column 0
  // answered in place. Batches of kResponseBatch and the remainders 1 and 2.
  const int n = 12;
  const Model model = random_chain(n, 91);
  Data data(model);
  forward_kinematics(model, data, Eigen::VectorXd::Random(n));
  articulated_inertias(model, data);
  mass_matrix_crba(model, data);
  const Eigen::LLT<Eigen::MatrixXd> llt(data.mass_matrix);
  for (int m = 0; m <= 7; ++m) {
    CAPTURE(m);
    Eigen::MatrixXd T = Eigen::MatrixXd::Random(std::max(m, 1), n);  // row k: column k's torques
    for (int k = 0; k < m; ++k) T.row(k).tail(k).setZero();
    Eigen::MatrixXd X = Eigen::MatrixXd::Constant(n, std::max(m, 1), 7.0);
    Eigen::VectorXd in_place = T.row(0).transpose();
    std::vector<ResponseColumn> columns;
    for (int k = 0; k < m; ++k)
      columns.push_back(k == 0 ? ResponseColumn{in_place.data(), 1, in_place.data()}
                               : ResponseColumn{T.data() + k, T.outerStride(), X.col(k).data()});
    aba_responses(model, data, columns.data(), m);
    for (int k = 0; k < m; ++k) {
      CAPTURE(k);
      const Eigen::VectorXd tau = T.row(k).transpose();
      Eigen::VectorXd one(n);
      aba_response(model, data, tau, one);
      const Eigen::VectorXd x = k == 0 ? in_place : Eigen::VectorXd(X.col(k));
      CHECK(approx(x, one, 0.0));
      const Eigen::VectorXd expected = llt.solve(tau);
      CHECK(approx(x, expected, 1e-10 * expected.cwiseAbs().maxCoeff()));
    }
    if (m == 0) CHECK(X.isConstant(7.0));  // nothing swept, nothing written
  }
}

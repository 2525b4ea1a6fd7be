// Lemke's method (engine/contact/lemke): complementary solutions of P-matrix
// and positive semi-definite LCPs (dependent contact rows), a clean failure
// on an infeasible one, no allocation.
#include <doctest/doctest.h>

#include <random>

#include "engine/contact/lemke.hpp"
#include "engine/contact/lcp.hpp"

using namespace elbowsim;

namespace {

// w >= -tol, z >= -tol, |z_i w_i| <= tol for every i.
bool complementary(const Eigen::VectorXd& z, const Eigen::VectorXd& w, double tol) {
  for (Eigen::Index i = 0; i < z.size(); ++i)
    if (z[i] < -tol || w[i] < -tol || std::abs(z[i] * w[i]) > tol) return false;
  return true;
}

}  // namespace

TEST_CASE("Lemke: P-matrix LCPs have one solution; it is Murty's (lcp.hpp)") {
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  LemkeScratch scratch(8);
  for (int trial = 0; trial < 300; ++trial) {
    const int p = 1 + trial % 8;
    Eigen::MatrixXd B(p, p);
    for (auto& v : B.reshaped()) v = n(rng);
    const Eigen::MatrixXd M = B * B.transpose() + 0.1 * Eigen::MatrixXd::Identity(p, p);
    Eigen::VectorXd q(p);
    for (auto& v : q) v = n(rng);
    Eigen::VectorXd z(p), w(p), f, wm;
    const LemkeResult r = solve_lemke(M, q, z, w, scratch);
    REQUIRE(r.solved);
    CHECK(complementary(z, w, 1e-10));
    std::vector<bool> active(p, false);
    REQUIRE(solve_lcp(M, q, 1e-12, 1e-12, f, wm, active).solved);
    CHECK((z - f).cwiseAbs().maxCoeff() < 1e-9 * (1 + f.cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("Lemke: dependent rows (positive semi-definite M) still give a complementary solution") {
  // M = J J^T with 6 rows of rank 3, q = J c + d: feasible (Gauss's principle
  // has a minimiser); degenerate pivots are where cycling would show.
  std::mt19937 rng(9);
  std::normal_distribution<double> n;
  LemkeScratch scratch(12);
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int p = 6 + trial % 6, rank = 3;
    Eigen::MatrixXd J(p, rank);
    for (auto& v : J.reshaped()) v = n(rng);
    Eigen::VectorXd c(rank);
    for (auto& v : c) v = n(rng);
    const Eigen::MatrixXd M = J * J.transpose();
    const Eigen::VectorXd q = J * c + 0.1 * Eigen::VectorXd::Ones(p);
    Eigen::VectorXd z(p), w(p);
    const LemkeResult r = solve_lemke(M, q, z, w, scratch);
    CAPTURE(trial);
    REQUIRE(r.solved);
    solved += complementary(z, w, 1e-9);
  }
  CHECK(solved == 200);
}

TEST_CASE("Lemke: an infeasible LCP ends by ray termination, not a wrong answer") {
  // w = -z - 1 >= 0 has no solution with z >= 0.
  LemkeScratch scratch(3);
  Eigen::VectorXd z(3), w(3);
  const LemkeResult r = solve_lemke(-Eigen::MatrixXd::Identity(3, 3), -Eigen::VectorXd::Ones(3), z,
                                    w, scratch);
  CHECK_FALSE(r.solved);
}

TEST_CASE("Lemke allocates nothing") {
  LemkeScratch scratch(6);
  const Eigen::MatrixXd M = Eigen::MatrixXd::Random(6, 6) + 6 * Eigen::MatrixXd::Identity(6, 6);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(6) - Eigen::VectorXd::Ones(6);
  Eigen::VectorXd z(6), w(6);
  Eigen::internal::set_is_malloc_allowed(false);
  const LemkeResult r = solve_lemke(M, q, z, w, scratch);
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(r.solved);
  CHECK(complementary(z, w, 1e-10));
}

// engine/contact/min_norm_solve.cpp: x = A^+ b from a complete orthogonal decomposition,
// the same bits as Eigen's CompleteOrthogonalDecomposition::solve, without allocating.
#include <doctest/doctest.h>

#include <Eigen/QR>
#include <cstring>
#include <random>

#include "engine/contact/min_norm_solve.hpp"
#include "support/allocations.hpp"

using namespace elbowsim;
using elbowsim::testing::allocation_count;
using elbowsim::testing::malloc_count;

namespace {

// An m x m matrix of rank r (r = m: full rank), entries of order 1.
Eigen::MatrixXd of_rank(int m, int r, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd U(m, r), V(m, r);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < r; ++j) U(i, j) = normal(rng), V(i, j) = normal(rng);
  return U * V.transpose();
}

}  // namespace

TEST_CASE("min_norm_solve == CompleteOrthogonalDecomposition::solve bit for bit, sizes 1-8, any rank") {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  int cases = 0;
  for (int m = 1; m <= 8; ++m) {
    for (const int r : {m, m - 1, m / 2, 0}) {
      CAPTURE(m);
      CAPTURE(r);
      const Eigen::MatrixXd A = of_rank(m, r, rng);
      Eigen::VectorXd b(m);
      for (int i = 0; i < m; ++i) b[i] = normal(rng);
      SolverWorkspace ws(m, 3);
      ws.cod.compute(A);
      ws.cod.setThreshold(1e-9);  // the engine's rank_tolerance
      REQUIRE(ws.cod.rank() == r);
      const Eigen::VectorXd expected = ws.cod.solve(b);
      Eigen::VectorXd x = Eigen::VectorXd::Constant(m, 7.0);
      const long news = allocation_count();
      Eigen::internal::set_is_malloc_allowed(false);
      min_norm_solve(ws, b, x);
      Eigen::internal::set_is_malloc_allowed(true);
      CHECK(allocation_count() == news);  // operator new; Eigen's malloc: the next test
      CHECK(std::memcmp(x.data(), expected.data(), sizeof(double) * std::size_t(m)) == 0);
      // And it is the minimum-norm least-squares solution: the residual is orthogonal to
      // the range of A, and x lies in the range of A^T. Rounding with a condition number
      // of at most ~1e3 on these sizes: 1e-9.
      CHECK((A.transpose() * (A * x - b)).norm() < 1e-9 * (1 + A.norm() * A.norm() * x.norm()));
      if (r > 0) {
        const Eigen::MatrixXd range = A.transpose().colPivHouseholderQr().householderQ() *
                                      Eigen::MatrixXd::Identity(m, r);
        CHECK((x - range * (range.transpose() * x)).norm() < 1e-9 * (1 + x.norm()));
      }
      ++cases;
    }
  }
  CHECK(cases == 32);
}

TEST_CASE("min_norm_solve calls the C allocator zero times (sizes 1-8, any rank)") {
  std::mt19937 rng(6);
  std::normal_distribution<double> normal;
  for (int m = 1; m <= 8; ++m) {
    for (const int r : {m, m / 2}) {
      const Eigen::MatrixXd A = of_rank(m, r, rng);
      Eigen::VectorXd b(m), x(m);
      for (int i = 0; i < m; ++i) b[i] = normal(rng);
      SolverWorkspace ws(m, 3);
      ws.cod.compute(A);
      ws.cod.setThreshold(1e-9);
      const long mallocs = malloc_count();
      min_norm_solve(ws, b, x);
      const long calls = malloc_count() - mallocs;
      CAPTURE(m);
      CAPTURE(r);
      CHECK(calls == 0);
    }
  }
}

// engine/contact/lcp.cpp: unilateral contact as a linear complementarity problem.
#include <doctest/doctest.h>

#include <Eigen/Cholesky>
#include <random>

#include "engine/contact/lcp.hpp"

using namespace elbowsim;

namespace {

bool complementary(const Eigen::VectorXd& f, const Eigen::VectorXd& w, double tol) {
  for (Eigen::Index k = 0; k < f.size(); ++k)
    if (f[k] < -tol || w[k] < -tol || std::abs(f[k] * w[k]) > tol) return false;
  return true;
}

// "Drop every negative force once and re-solve": solve with all rows on,
// drop the rows with f < 0, solve again, stop.
void naive(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, Eigen::VectorXd& f,
           Eigen::VectorXd& w) {
  const int p = int(b.size());
  f = A.ldlt().solve(-b);
  std::vector<int> keep;
  for (int k = 0; k < p; ++k)
    if (f[k] >= 0) keep.push_back(k);
  f.setZero(p);
  Eigen::MatrixXd As(keep.size(), keep.size());
  Eigen::VectorXd bs(keep.size());
  for (std::size_t r = 0; r < keep.size(); ++r) {
    bs[r] = -b[keep[r]];
    for (std::size_t c = 0; c < keep.size(); ++c) As(r, c) = A(keep[r], keep[c]);
  }
  const Eigen::VectorXd fs = As.ldlt().solve(bs);
  for (std::size_t r = 0; r < keep.size(); ++r) f[keep[r]] = fs[r];
  w = A * f + b;
}

}  // namespace

TEST_CASE("lcp: interacting contacts where naive dropping picks the wrong set") {
  // Delassus-like SPD matrices with strong coupling between rows, as three
  // elbows on one arm give. Search a fixed random sequence for a case the
  // naive rule gets wrong, then check the pivoting solver gets it right.
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  int naive_failures = 0, checked = 0;
  for (int trial = 0; trial < 2000 && naive_failures < 20; ++trial) {
    Eigen::MatrixXd J(3, 4);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) J(r, c) = normal(rng);
    const Eigen::MatrixXd A = J * J.transpose();
    Eigen::VectorXd b(3);
    for (int r = 0; r < 3; ++r) b[r] = normal(rng);
    Eigen::VectorXd fn, wn, f, w;
    naive(A, b, fn, wn);
    if (complementary(fn, wn, 1e-9)) continue;
    ++naive_failures;
    std::vector<bool> active;
    const LcpResult r = solve_lcp(A, b, 1e-12, 1e-12, f, w, active);
    CHECK(r.solved);
    CHECK(complementary(f, w, 1e-9));
    ++checked;
  }
  MESSAGE("cases where naive dropping fails: ", naive_failures);
  CHECK(checked >= 10);
}

TEST_CASE("lcp: the solution is unique for a P-matrix, whatever the warm start") {
  Eigen::MatrixXd A(3, 3);
  A << 2.0, 1.2, -0.5, 1.2, 1.5, 0.3, -0.5, 0.3, 1.0;
  const Eigen::VectorXd b = Eigen::Vector3d(-1.0, 0.5, -0.2);
  Eigen::VectorXd reference;
  for (unsigned start = 0; start < 8; ++start) {
    std::vector<bool> active = {bool(start & 1), bool(start & 2), bool(start & 4)};
    Eigen::VectorXd f, w;
    REQUIRE(solve_lcp(A, b, 1e-12, 1e-12, f, w, active).solved);
    CHECK(complementary(f, w, 1e-12));
    if (start == 0) reference = f;
    CHECK((f - reference).norm() < 1e-12);
  }
}

TEST_CASE("lcp: dependent rows give minimum-norm forces and say so") {
  // Two identical rows (two elbows at one point) plus one independent.
  Eigen::MatrixXd J(3, 3);
  J << 1, 0.5, 0, 1, 0.5, 0, 0, 1, 1;
  const Eigen::MatrixXd A = J * J.transpose();
  const Eigen::VectorXd b = Eigen::Vector3d(-1.0, -1.0, -0.5);
  Eigen::VectorXd f, w;
  std::vector<bool> active(3, true);
  const LcpResult r = solve_lcp(A, b, 1e-9, 1e-12, f, w, active);
  CHECK(r.solved);
  CHECK(r.dependent);
  CHECK(f.allFinite());
  CHECK(complementary(f, w, 1e-9));
  CHECK(std::abs(f[0] - f[1]) < 1e-9);  // minimum norm splits the load equally
}

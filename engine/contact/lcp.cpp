#include "engine/contact/lcp.hpp"

#include <Eigen/QR>
#include <vector>

namespace elbowsim {

namespace {

struct BlockSolver {
  const Eigen::MatrixXd& A;
  const Eigen::VectorXd& b;
  double rank_tolerance;
  bool dependent = false;

  // f_S = -A_SS^+ b_S (minimum norm), f elsewhere 0; w = A f + b.
  void solve(const std::vector<bool>& active, Eigen::VectorXd& f, Eigen::VectorXd& w) {
    std::vector<int> idx;
    for (int k = 0; k < int(active.size()); ++k)
      if (active[k]) idx.push_back(k);
    f.setZero(A.rows());
    if (!idx.empty()) {
      const int m = int(idx.size());
      Eigen::MatrixXd block(m, m);
      Eigen::VectorXd rhs(m);
      for (int r = 0; r < m; ++r) {
        rhs[r] = -b[idx[r]];
        for (int c = 0; c < m; ++c) block(r, c) = A(idx[r], idx[c]);
      }
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(block);
      cod.setThreshold(rank_tolerance);
      if (cod.rank() < m) dependent = true;
      const Eigen::VectorXd x = cod.solve(rhs);
      for (int r = 0; r < m; ++r) f[idx[r]] = x[r];
    }
    w = A * f + b;
  }
};

// Smallest index whose sign condition fails, or -1 when complementary.
int first_violation(const std::vector<bool>& active, const Eigen::VectorXd& f,
                    const Eigen::VectorXd& w, double tol) {
  for (int k = 0; k < int(active.size()); ++k) {
    if (active[k] && f[k] < -tol) return k;
    if (!active[k] && w[k] < -tol) return k;
  }
  return -1;
}

bool enumerate_sets(BlockSolver& solver, double tol, Eigen::VectorXd& f, Eigen::VectorXd& w,
                    std::vector<bool>& active) {
  const int p = int(active.size());
  for (int size = 0; size <= p; ++size) {
    for (unsigned mask = 0; mask < (1u << p); ++mask) {
      if (__builtin_popcount(mask) != size) continue;
      for (int k = 0; k < p; ++k) active[k] = (mask >> k) & 1u;
      solver.solve(active, f, w);
      if (first_violation(active, f, w, tol) < 0) return true;
    }
  }
  return false;
}

}  // namespace

LcpResult solve_lcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double rank_tolerance,
                    double tolerance, Eigen::VectorXd& f, Eigen::VectorXd& w,
                    std::vector<bool>& active) {
  const int p = int(b.size());
  LcpResult result;
  active.resize(p, false);
  const double tol = tolerance * std::max(b.cwiseAbs().maxCoeff(), 1e-300);
  BlockSolver solver{A, b, rank_tolerance};
  const int max_pivots = (1 << std::min(p, 20)) + p;
  for (; result.pivots <= max_pivots; ++result.pivots) {
    solver.solve(active, f, w);
    const int j = first_violation(active, f, w, tol);
    if (j < 0) {
      result.solved = true;
      break;
    }
    active[j] = !active[j];
  }
  if (!result.solved) result.solved = enumerate_sets(solver, tol, f, w, active);
  solver.dependent = false;  // report the rank of the final active block only
  solver.solve(active, f, w);
  result.dependent = solver.dependent;
  return result;
}

}  // namespace elbowsim

#include "engine/contact/lcp.hpp"

#include <cmath>

#include "engine/contact/min_norm_solve.hpp"

namespace elbowsim {

namespace {

struct BlockSolver {
  const Eigen::MatrixXd& A;
  const Eigen::VectorXd& b;
  double rank_tolerance;
  LcpScratch scratch;
  bool dependent = false;

  // f_S = -A_SS^+ b_S (minimum norm), f elsewhere 0; w = A f + b.
  void solve(const std::vector<bool>& active, Eigen::VectorXd& f, Eigen::VectorXd& w) {
    std::vector<int>& idx = scratch.index;
    idx.clear();
    for (int k = 0; k < int(active.size()); ++k)
      if (active[k]) idx.push_back(k);
    f.setZero(A.rows());
    if (!idx.empty()) {
      const int m = int(idx.size());
      SolverWorkspace& ws = scratch.blocks[static_cast<std::size_t>(m)];
      for (int r = 0; r < m; ++r) {
        ws.rhs[r] = -b[idx[r]];
        for (int c = 0; c < m; ++c) ws.block(r, c) = A(idx[r], idx[c]);
      }
      ws.cod.compute(ws.block);
      ws.cod.setThreshold(rank_tolerance);
      if (ws.cod.rank() < m) dependent = true;
      min_norm_solve(ws, ws.rhs, ws.x);
      for (int r = 0; r < m; ++r) f[idx[r]] = ws.x[r];
    }
    w.noalias() = A * f;
    w += b;
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

// Complementary up to tol, for a solution not tied to an active set.
bool first_violation_free(const Eigen::VectorXd& f, const Eigen::VectorXd& w, double tol) {
  for (Eigen::Index k = 0; k < f.size(); ++k)
    if (f[k] < -tol || w[k] < -tol || std::abs(f[k] * w[k]) > tol * std::max(1.0, std::abs(f[k])))
      return false;
  return true;
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
                    std::vector<bool>& active, LcpScratch scratch) {
  const int p = int(b.size());
  LcpResult result;
  active.resize(p, false);
  const double tol = tolerance * std::max(b.cwiseAbs().maxCoeff(), 1e-300);
  BlockSolver solver{A, b, rank_tolerance, scratch};
  const int max_pivots = (1 << std::min(p, 12)) + p;
  for (; result.pivots <= max_pivots; ++result.pivots) {
    solver.solve(active, f, w);
    const int j = first_violation(active, f, w, tol);
    if (j < 0) {
      result.solved = true;
      break;
    }
    active[j] = !active[j];
  }
  // Lemke's solution as it is: with dependent rows the minimum-norm forces of
  // its active set could be negative.
  if (!result.solved && scratch.lemke && p <= scratch.lemke->capacity()) {
    const LemkeResult lemke = solve_lemke(A, b, f, w, *scratch.lemke);
    result.pivots += lemke.pivots;
    if (lemke.solved && first_violation_free(f, w, tol)) {
      for (int k = 0; k < p; ++k) active[k] = f[k] > tol;
      result.solved = true;
      result.dependent = true;
      return result;
    }
  }
  if (!result.solved && p <= 12) result.solved = enumerate_sets(solver, tol, f, w, active);
  solver.dependent = false;  // report the rank of the final active block only
  solver.solve(active, f, w);
  result.dependent = solver.dependent;
  return result;
}

LcpResult solve_lcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double rank_tolerance,
                    double tolerance, Eigen::VectorXd& f, Eigen::VectorXd& w,
                    std::vector<bool>& active) {
  const int p = int(b.size());
  std::vector<SolverWorkspace> blocks;
  blocks.reserve(static_cast<std::size_t>(p) + 1);
  for (int m = 0; m <= p; ++m) blocks.emplace_back(m, 0);
  std::vector<int> index;
  index.reserve(static_cast<std::size_t>(p));
  f.resize(p);
  w.resize(p);
  return solve_lcp(A, b, rank_tolerance, tolerance, f, w, active, LcpScratch{blocks, index});
}

}  // namespace elbowsim

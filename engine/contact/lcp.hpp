// Small linear complementarity problems for unilateral contact:
//   find f >= 0 with w = A f + b >= 0 and f_k w_k = 0 for every k,
// for the p x p Delassus matrix A = Jc M^-1 Jc^T (p = elbows in touch, a few).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "engine/contact/contact_data.hpp"
#include "engine/contact/lemke.hpp"

namespace elbowsim {

struct LcpResult {
  bool solved = false;   // a complementary solution was found
  bool dependent = false;  // some active block was rank deficient (min-norm forces used)
  int pivots = 0;        // principal pivots taken
};

// Scratch for the block solves: one workspace per block size m (index m,
// up to p) and room for p indices. With it solve_lcp allocates nothing.
struct LcpScratch {
  std::vector<SolverWorkspace>& blocks;
  std::vector<int>& index;
  LemkeScratch* lemke = nullptr;  // the fallback's scratch (lemke.hpp), if any
};

// Murty's least-index principal pivoting (finite for P-matrices, i.e. when
// the rows are independent), warm-started from `active` (true = f_k may be
// > 0). If it does not finish in 2^min(p, 12) + p pivots (dependent rows can
// make it cycle), Lemke's method (lemke.hpp, with scratch.lemke) takes over,
// and for p <= 12 every active set is tried last, in order of size, each
// block solved for minimum-norm forces. Blocks are solved with a complete orthogonal
// decomposition whose rank threshold is `rank_tolerance` (relative).
// `tolerance` is the complementarity slack, relative to max(|b|, 1e-300).
// On return `active` marks the rows with f_k > 0 (or w_k == 0 at the solution).
// f and w [p] must not alias A or b.
LcpResult solve_lcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double rank_tolerance,
                    double tolerance, Eigen::VectorXd& f, Eigen::VectorXd& w,
                    std::vector<bool>& active, LcpScratch scratch);

// The same with scratch of its own (allocates; for planning and tests).
LcpResult solve_lcp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double rank_tolerance,
                    double tolerance, Eigen::VectorXd& f, Eigen::VectorXd& w,
                    std::vector<bool>& active);

}  // namespace elbowsim

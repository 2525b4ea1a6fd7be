// Lemke's complementary pivoting for the linear complementarity problem
//   w = M z + q,  w >= 0,  z >= 0,  z . w = 0
// with covering vector e and lexicographic ratio tests (no cycling on
// degenerate problems). It solves every LCP whose matrix is copositive-plus
// (positive semi-definite ones included: dependent contact rows) and
// feasible, and the Coulomb friction LCPs whose matrices are not symmetric;
// Murty's principal pivoting (lcp.hpp) is faster when M is a P-matrix, and
// falls back to this.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace elbowsim {

// Scratch for problems of up to `capacity` rows, sized once.
struct LemkeScratch {
  explicit LemkeScratch(int capacity = 0);
  Eigen::MatrixXd inverse;  // [capacity x capacity] basis inverse
  Eigen::VectorXd x, column, scaled;  // [capacity]
  std::vector<int> basis;   // [capacity] basic variable per row: w_i = i, z_i = p + i, z0 = 2p
  int capacity() const { return static_cast<int>(x.size()); }
};

struct LemkeResult {
  bool solved = false;  // false: ray termination (infeasible, or M not copositive-plus) or too many pivots
  int pivots = 0;
};

// Solves the p x p problem (p = q.size() <= scratch.capacity()) into z and
// w (size p). Allocates nothing. `tolerance` is the smallest pivot, relative
// to the largest |M_ij| (or 1).
LemkeResult solve_lemke(const Eigen::Ref<const Eigen::MatrixXd>& M,
                        const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::Ref<Eigen::VectorXd> z,
                        Eigen::Ref<Eigen::VectorXd> w, LemkeScratch& scratch,
                        double tolerance = 1e-12);

}  // namespace elbowsim

#include "engine/contact/min_norm_solve.hpp"

namespace elbowsim {

// Eigen 3.4's CompleteOrthogonalDecomposition::_solve_impl, step by step:
// c = Q^* b; z = T(1:r, 1:r)^-1 c(1:r); y = Z^* [z; 0]; x = P y.
void min_norm_solve(SolverWorkspace& ws, ConstVec b, Eigen::Ref<Eigen::VectorXd> x) {
  const auto& cod = ws.cod;
  const Eigen::Index rank = cod.rank(), cols = cod.cols();
  if (rank == 0) {
    x.setZero();
    return;
  }
  Eigen::VectorXd& c = ws.work;
  c = b;
  c.applyOnTheLeft(cod.matrixQ().setLength(rank).adjoint());
  x.head(rank) = cod.matrixT()
                     .topLeftCorner(rank, rank)
                     .template triangularView<Eigen::Upper>()
                     .solve(c.head(rank));
  if (rank < cols) {
    // Eigen's applyZAdjointOnTheLeftInPlace, with our scratch for its temporary.
    x.tail(cols - rank).setZero();
    for (Eigen::Index k = 0; k < rank; ++k) {
      if (k != rank - 1) x.row(k).swap(x.row(rank - 1));
      x.middleRows(rank - 1, cols - rank + 1)
          .applyHouseholderOnTheLeft(cod.matrixQTZ().row(k).tail(cols - rank).adjoint(),
                                     cod.zCoeffs()(k), &ws.work_cols(0));
      if (k != rank - 1) x.row(k).swap(x.row(rank - 1));
    }
  }
  c = x;  // the permutation, out of place (in place, Eigen allocates a mask)
  x = cod.colsPermutation() * c;
}

}  // namespace elbowsim

#include "engine/contact/min_norm_solve.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/pad.hpp"

namespace elbowsim {

namespace {

// Eigen's MatrixBase::applyHouseholderOnTheLeft for a vector x (the reflector
// I - tau [1; v] [1; v]^T), written out: Eigen's own evaluates tau v into a
// heap temporary for the outer product.
template <typename Vector, typename Essential>
void reflect(Vector x, const Essential& v, double tau) {
  if (x.size() == 1) {
    x[0] *= 1.0 - tau;
    return;
  }
  if (tau == 0) return;
  double tmp = v.dot(x.tail(x.size() - 1));  // Eigen's inner product: the same sum as dot()
  tmp += x[0];
  x[0] -= tau * tmp;
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i) x[i + 1] -= (tau * v[i]) * tmp;
}

// The Delassus solve without friction for p <= kSmallRows rows, on the stack:
// Cholesky A = L L^T (Eigen's unblocked LLT, written out), then the two
// substitutions. Eigen's dynamic-size LLT costs more in calls and bookkeeping
// than these few dozen flops. False (fn untouched) when A is not positive
// definite or a pivot L_kk^2 is at most tol times the largest: dependent rows.
constexpr int kSmallRows = 4;
bool small_cholesky_solve(const ContactData& c, double tol, Eigen::Ref<Eigen::VectorXd> fn) {
  const int p = static_cast<int>(c.A.rows());
  double L[kSmallRows][kSmallRows];
  double largest = 0, smallest = 0;
  for (int k = 0; k < p; ++k) {
    double d = c.A(k, k);
    for (int j = 0; j < k; ++j) d -= L[k][j] * L[k][j];
    if (!(d > 0)) return false;
    largest = k == 0 ? d : std::max(largest, d);
    smallest = k == 0 ? d : std::min(smallest, d);
    L[k][k] = std::sqrt(d);
    for (int i = k + 1; i < p; ++i) {
      double x = c.A(i, k);
      for (int j = 0; j < k; ++j) x -= L[i][j] * L[k][j];
      L[i][k] = x / L[k][k];
    }
  }
  if (!(smallest > tol * largest)) return false;
  double y[kSmallRows];
  for (int i = 0; i < p; ++i) {
    double x = c.rhs[i];
    for (int j = 0; j < i; ++j) x -= L[i][j] * y[j];
    y[i] = x / L[i][i];
  }
  for (int i = p - 1; i >= 0; --i) {
    double x = y[i];
    for (int j = i + 1; j < p; ++j) x -= L[j][i] * fn[j];
    fn[i] = x / L[i][i];
  }
  return true;
}

}  // namespace

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
  // Q^* c = H_{r-1} ... H_1 H_0 c (HouseholderSequence::applyThisOnTheLeft of the adjoint).
  const auto& qr = cod.matrixQTZ();
  const Eigen::Index rows = qr.rows();
  for (Eigen::Index k = 0; k < rank; ++k)
    reflect(c.tail(rows - k), qr.col(k).tail(rows - k - 1), cod.hCoeffs()(k));
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

void rank_revealing_solve(const Model& model, ContactData& c) {
  c.dependent = false;
  if (c.rows() == 0) return;  // no rows, no forces
  prescribe_pad_rows(model, c);
  SolverWorkspace& ws = c.solver(c.rows());
  const double tol = model.contact.rank_tolerance;
  bool independent;
  if (model.effects.friction || model.has_pads()) {  // A is not symmetric
    ws.lu.compute(c.A);
    const auto pivots = ws.lu.matrixLU().diagonal().cwiseAbs();
    independent = pivots.minCoeff() > tol * pivots.maxCoeff();
    if (independent) c.fn = ws.lu.solve(c.rhs);
  } else if (c.rows() <= kSmallRows) {
    independent = small_cholesky_solve(c, tol, c.fn);
  } else {
    ws.llt.compute(c.A);
    const auto pivots = ws.llt.matrixLLT().diagonal().cwiseAbs2();
    independent = ws.llt.info() == Eigen::Success && pivots.minCoeff() > tol * pivots.maxCoeff();
    if (independent) {
      c.fn = c.rhs;
      ws.llt.solveInPlace(c.fn);
    }
  }
  c.dependent = !independent;
  if (independent) return;
  ws.cod.compute(c.A);
  ws.cod.setThreshold(tol);
  min_norm_solve(ws, c.rhs, c.fn);
}

}  // namespace elbowsim

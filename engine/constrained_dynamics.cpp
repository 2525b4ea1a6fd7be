#include "constrained_dynamics.hpp"

#include <Eigen/LU>
#include <Eigen/QR>

namespace elbowsim {

namespace {

// f = A^+ rhs with a complete orthogonal decomposition: exact for
// independent rows, minimum-norm when rows are dependent.
void rank_revealing_solve(const Model& model, Data& data) {
  ContactData& c = data.contact;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(c.A);
  cod.setThreshold(model.contact.rank_tolerance);
  c.dependent = cod.rank() < c.A.rows();
  c.fn = cod.solve(c.rhs);
}

// Schur complement: with M = L L^T, Y = L^-1 Jc^T, Z = L^-1 Jf^T,
// A = Y^T Z, f = A^-1 (gamma - Jc a_free), qdd = a_free + L^-T Z f.
void schur(const Model& model, Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  data.llt.compute(data.mass_matrix);
  c.a_free = tau - data.bias;
  data.llt.solveInPlace(c.a_free);
  const auto L = data.llt.matrixL();
  c.Y = L.solve(c.Jc.transpose());
  c.Z = model.effects.friction ? Eigen::MatrixXd(L.solve(c.Jf.transpose())) : c.Y;
  c.A = c.Y.transpose() * c.Z;
  c.rhs = c.gamma - c.Jc * c.a_free;
  rank_revealing_solve(model, data);
  data.qdd = c.Z * c.fn;
  data.llt.matrixU().solveInPlace(data.qdd);
  data.qdd += c.a_free;
}

void dense_lu(Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  const Eigen::Index n = data.mass_matrix.rows(), p = c.Jc.rows();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + p, n + p);
  K.topLeftCorner(n, n) = data.mass_matrix;
  K.topRightCorner(n, p) = -c.Jf.transpose();
  K.bottomLeftCorner(p, n) = c.Jc;
  Eigen::VectorXd rhs(n + p);
  rhs << tau - data.bias, c.gamma;
  const Eigen::VectorXd x = K.partialPivLu().solve(rhs);
  data.qdd = x.head(n);
  c.fn = x.tail(p);
}

// Paper eq. (48)-(49) with explicit inverses.
void explicit_inverse(Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  const Eigen::MatrixXd M_inv = data.mass_matrix.inverse();
  const Eigen::MatrixXd M_tilde_inv = (c.Jc * M_inv * c.Jf.transpose()).inverse();
  const Eigen::VectorXd tau_prime = tau - data.bias;
  c.fn = M_tilde_inv * (c.gamma - c.Jc * M_inv * tau_prime);
  data.qdd = M_inv * (tau_prime + c.Jf.transpose() * c.fn);
}

}  // namespace

void solve_constrained(const Model& model, Data& data, ConstVec tau, ConstraintSolver method) {
  switch (method) {
    case ConstraintSolver::schur: schur(model, data, tau); return;
    case ConstraintSolver::dense_lu: dense_lu(data, tau); return;
    case ConstraintSolver::explicit_inverse: explicit_inverse(data, tau); return;
  }
}

void contact_lcp_terms(const Model& model, Data& data, ConstVec tau, Eigen::MatrixXd& A,
                       Eigen::VectorXd& b) {
  schur(model, data, tau);  // leaves A, a_free
  A = data.contact.A;
  b = data.contact.Jc * data.contact.a_free - data.contact.gamma;
}

}  // namespace elbowsim

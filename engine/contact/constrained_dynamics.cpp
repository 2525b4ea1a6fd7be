#include "engine/contact/constrained_dynamics.hpp"

#include <Eigen/LU>
#include <Eigen/QR>

#include "engine/contact/aba_contact.hpp"
#include "engine/contact/min_norm_solve.hpp"
#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/joint_friction.hpp"
#include "engine/dynamics/walker_orin.hpp"

namespace elbowsim {

namespace {

// Zeroes the stuck joints' rows of an n-row matrix or vector.
template <class Rows>
void zero_stuck_rows(const Data& data, Rows&& x) {
  for (Eigen::Index j = 0; j < x.rows(); ++j)
    if (data.joint_mode[static_cast<std::size_t>(j)] == 0) x.row(j).setZero();
}

// Schur complement. With M = L L^T, w = L^-1 (tau - B_J), Y = L^-1 Jc^T and
// Z = L^-1 Jf^T: A = Y^T Z, f = A^-1 (gamma - Y^T w), qdd = L^-T (w + Z f).
// Three triangular solves and one p x p factorisation. Stuck joints are
// locked: their rows and columns of M become the identity and their entries
// of tau - B_J, Jc^T and Jf^T zero, so the same solve gives the reduced
// system's f and qdd with qdd_j = 0 exactly (L keeps them uncoupled).
void schur(const Model& model, Data& data, ConstVec tau) {
  ContactData& c = data.contact;
  const bool locked = any_joint_stuck(model, data);
  if (locked) lock_stuck_joints(data);
  data.llt.compute(locked ? data.joint_mass : data.mass_matrix);
  const auto L = data.llt.matrixL();
  c.a_free = tau - data.bias;  // becomes w
  c.Y = c.Jc.transpose();
  if (locked) {
    zero_stuck_rows(data, c.a_free);
    zero_stuck_rows(data, c.Y);
  }
  L.solveInPlace(c.a_free);
  // Eigen's triangular solve binds a reference to coefficient (0, 0) even
  // with no columns (undefined behaviour on an empty matrix): p = 0 skips it.
  if (c.Y.cols() > 0) L.solveInPlace(c.Y);
  const Eigen::MatrixXd* Z = &c.Y;  // without friction Jf = Jc
  if (model.effects.friction) {
    c.Z = c.Jf.transpose();
    if (locked) zero_stuck_rows(data, c.Z);
    if (c.Z.cols() > 0) L.solveInPlace(c.Z);
    Z = &c.Z;
  }
  c.A.noalias() = c.Y.transpose() * *Z;
  c.rhs = c.gamma;
  c.rhs.noalias() -= c.Y.transpose() * c.a_free;
  rank_revealing_solve(model, c);
  data.qdd = c.a_free;
  data.qdd.noalias() += *Z * c.fn;
  data.llt.matrixU().solveInPlace(data.qdd);
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

ConstraintSolver constraint_solver(const Model& model) {
  ConstraintSolver s = model.contact.solver;
  // auto: aba from the crossover on; the paper's pipeline (Walker-Orin's M,
  // then the Schur complement) stays whole when simulation.dynamics asks for it.
  if (s == ConstraintSolver::automatic)
    s = model.dof >= kAbaCrossover && model.options.dynamics != DynamicsMethod::walker_orin
            ? ConstraintSolver::aba
            : ConstraintSolver::schur;
  if (s == ConstraintSolver::aba && model.effects.joint_friction) s = ConstraintSolver::schur;
  return s;
}

void constrained_mechanics(const Model& model, Data& data, ConstVec qd) {
  if (constraint_solver(model) == ConstraintSolver::aba)
    articulated_inertias(model, data);
  else if (model.options.dynamics == DynamicsMethod::walker_orin)
    mass_matrix_walker_orin(model, data);
  else
    mass_matrix_crba(model, data);
  bias_torques(model, data, qd);
}

void solve_constrained(const Model& model, Data& data, ConstVec tau, ConstraintSolver method) {
  if (method == ConstraintSolver::automatic) method = constraint_solver(model);
  if (any_joint_stuck(model, data)) method = ConstraintSolver::schur;  // the one that locks joints
  // Dependent rows (found by the step start's solve) make M* singular: the
  // explicit inverse returns NaN and the dense LU an arbitrary split. The
  // Schur solve gives the minimum-norm one (the warning says so).
  // The aba path forms the same A and gives the same minimum-norm split.
  if (data.contact.dependent && method != ConstraintSolver::aba) method = ConstraintSolver::schur;
  switch (method) {
    case ConstraintSolver::automatic:  // resolved above
    case ConstraintSolver::schur: schur(model, data, tau); return;
    case ConstraintSolver::aba: aba_contact_solve(model, data, tau); return;
    case ConstraintSolver::dense_lu: dense_lu(data, tau); return;
    case ConstraintSolver::explicit_inverse: explicit_inverse(data, tau); return;
  }
}

void contact_lcp_terms(const Model& model, Data& data, ConstVec tau) {
  // Either solve leaves A, rhs = gamma - Jc qdd_free, and the rank decision
  // (data.contact.dependent) that the active set reads.
  if (constraint_solver(model) == ConstraintSolver::aba)
    aba_contact_solve(model, data, tau);
  else
    schur(model, data, tau);
  data.contact.lcp_b = -data.contact.rhs;
}

}  // namespace elbowsim

// The mechanical block of the paper's system M* [qdd; f_n; di/dt] = b
// (eq. 32-38): with the current block diagonal and decoupled (di/dt comes
// from the motor model directly), what is left is the saddle-point system
//   [ M + Jm   -Jf^T ] [ qdd ]   [ tau - B_J ]
//   [   Jc       0   ] [ f_n ] = [  gamma    ]
// (Jf = Jc without friction). Three ways to solve it:
//   schur            Cholesky of M + Jm, then the p x p Schur complement
//                    A = Jc M^-1 Jf^T (the paper's M~, eq. 49) by a
//                    rank-revealing factorisation: the production path;
//   dense_lu         LU of the whole (n+p) x (n+p) matrix: a reference;
//   explicit_inverse the paper's closed form (46)-(48) with M^-1 and M~^-1
//                    formed explicitly: kept as the paper's method.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Needs data.mass_matrix (= M + Jm) and data.bias (= B_J) at the current
// state and constraint_rows(). tau [n] are the applied joint torques. Joints
// stuck by joint friction (data.joint_mode 0) are locked, qdd_j = 0 (always
// by the Schur path; their holding torques: dynamics/joint_friction.hpp). Fills
// data.qdd and data.contact.fn; data.contact.dependent tells whether the
// rows were dependent (rank below p at model.contact.rank_tolerance), in
// which case f_n is the minimum-norm solution.
void solve_constrained(const Model& model, Data& data, ConstVec tau, ConstraintSolver method);
// With the scene's solver (model.contact.solver).
inline void solve_constrained(const Model& model, Data& data, ConstVec tau) {
  solve_constrained(model, data, tau, model.contact.solver);
}

// The Delassus matrix A = Jc (M + Jm)^-1 Jf^T into data.contact.A and the
// free constraint acceleration b = Jc qdd_free - gamma into data.contact.lcp_b,
// for the active-set (LCP) decision: the normal accelerations are w = A f + b.
// Needs the same inputs.
void contact_lcp_terms(const Model& model, Data& data, ConstVec tau);

}  // namespace elbowsim

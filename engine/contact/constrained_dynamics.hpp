// The mechanical block of the paper's system M* [qdd; f_n; di/dt] = b
// (eq. 32-38): with the current block diagonal and decoupled (di/dt comes
// from the motor model directly), what is left is the saddle-point system
//   [ M + Jm   -Jf^T ] [ qdd ]   [ tau - B_J ]
//   [   Jc       0   ] [ f_n ] = [  gamma    ]
// (Jf = Jc without friction). Four ways to solve it:
//   schur            Cholesky of M + Jm, then the p x p Schur complement
//                    A = Jc M^-1 Jf^T (the paper's M~, eq. 49) by a
//                    rank-revealing factorisation: O(n^3), and the
//                    path that locks joints stuck by joint friction;
//   aba              the same A and f from ABA's articulated inertias, one
//                    O(n) sweep per row, no M (contact/aba_contact.hpp):
//                    O(n p), the default (auto) from kAbaCrossover joints;
//   dense_lu         LU of the whole (n+p) x (n+p) matrix: a reference;
//   explicit_inverse the paper's closed form (46)-(48) with M^-1 and M~^-1
//                    formed explicitly: kept as the paper's method.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// contact.solver auto picks aba from this many joints on: the measured
// crossover of the whole constrained evaluation (bench/bench_derivative,
// DerivativeSchur against DerivativeAba): with Eigen's dynamic-size Cholesky
// the aba path was 2-16 % faster already at s = 2, 4, 7 for p = 1, 2, 4.
constexpr int kAbaCrossover = 2;

// The solver the scene's steps use: model.contact.solver, with auto resolved
// by the number of joints (schur with simulation.dynamics walker_orin, the
// paper's method end to end), and aba replaced by schur under joint friction
// (the Schur path locks stuck joints and the holding torques need M).
ConstraintSolver constraint_solver(const Model& model);

// What the solver needs at the current state (after forward_kinematics(q)):
// data.mass_matrix (by walker_orin or CRBA, as model.options.dynamics says)
// or, for aba, the articulated inertias (dynamics/aba.hpp); and data.bias.
void constrained_mechanics(const Model& model, Data& data, ConstVec qd);

// Needs data.mass_matrix (= M + Jm; aba: the articulated inertias instead)
// and data.bias (= B_J) at the current state and constraint_rows(). tau [n] are the applied joint torques. Joints
// stuck by joint friction (data.joint_mode 0) are locked, qdd_j = 0 (always
// by the Schur path; their holding torques: dynamics/joint_friction.hpp). Fills
// data.qdd and data.contact.fn; data.contact.dependent tells whether the
// rows were dependent (rank below p at model.contact.rank_tolerance), in
// which case f_n is the minimum-norm solution.
void solve_constrained(const Model& model, Data& data, ConstVec tau, ConstraintSolver method);
// With the scene's solver (constraint_solver(model)), after constrained_mechanics().
inline void solve_constrained(const Model& model, Data& data, ConstVec tau) {
  solve_constrained(model, data, tau, constraint_solver(model));
}

// The Delassus matrix A = Jc (M + Jm)^-1 Jf^T into data.contact.A and the
// free constraint acceleration b = Jc qdd_free - gamma into data.contact.lcp_b,
// for the active-set (LCP) decision: the normal accelerations are w = A f + b.
// Needs the same inputs (constrained_mechanics() for the scene's solver).
void contact_lcp_terms(const Model& model, Data& data, ConstVec tau);

}  // namespace elbowsim

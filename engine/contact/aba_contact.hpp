// The constrained step in O(n p) for long chains (contact.solver: aba): the
// same saddle-point system as the Schur path (constrained_dynamics.hpp),
//   [ M + Jm   -Jf^T ] [ qdd ]   [ tau - B_J ]
//   [   Jc       0   ] [ f_n ] = [  gamma    ],
// without forming or factoring M. With the articulated inertias of the arm
// at q (ABA's inward pass, dynamics/aba.hpp), one pair of O(n) sweeps gives
// (M + Jm)^-1 x for any joint torques x:
//   qdd_free = (M + Jm)^-1 (tau - B_J)            one sweep
//   X_k      = (M + Jm)^-1 Jf_k^T, k = 1 .. p     one sweep per row (unit-force response)
//   A = Jc X (the Delassus matrix, p x p), f = A^-1 (gamma - Jc qdd_free),
//   qdd = qdd_free + X f.
// Cost O(n p + n p^2 + p^3) against the Schur path's O(n^3 + n^2 p): the
// Cholesky of M is what makes that one grow with the cube of the chain.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// A = Jc (M + Jm)^-1 Jf^T into data.contact.A, rhs = gamma - Jc qdd_free into
// data.contact.rhs, qdd_free into data.contact.a_free and X into
// data.contact.Y. Needs articulated_inertias() (dynamics/aba.hpp), data.bias
// and constraint_rows() at the current state. tau [n]: applied joint torques.
void aba_contact_terms(const Model& model, Data& data, ConstVec tau);

// The whole solve: the terms above, then f (rank_revealing_solve: the
// minimum-norm f on dependent rows, as the Schur path) into data.contact.fn
// and qdd into data.qdd. Joints stuck by joint friction are not handled here
// (constraint_solver() never picks this path with joint friction on).
void aba_contact_solve(const Model& model, Data& data, ConstVec tau);

}  // namespace elbowsim

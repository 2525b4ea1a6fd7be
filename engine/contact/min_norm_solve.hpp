// Minimum-norm solutions of small, possibly rank-deficient contact systems,
// x = A^+ b, from a complete orthogonal decomposition. Eigen's own
// CompleteOrthogonalDecomposition::solve allocates temporaries on every call;
// this does the same operations, in the same order (so the same bits), in a
// workspace sized once.
#pragma once

#include "engine/contact/contact_data.hpp"

namespace elbowsim {

// Solves with the m x m matrix that `ws.cod` has factorised (after
// ws.cod.compute(A) and ws.cod.setThreshold(...)): x [m] = A^+ b [m].
// Uses ws.work and ws.work_cols; x must not be one of them.
void min_norm_solve(SolverWorkspace& ws, ConstVec b, Eigen::Ref<Eigen::VectorXd> x);

}  // namespace elbowsim

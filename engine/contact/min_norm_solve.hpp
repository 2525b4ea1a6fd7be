// Minimum-norm solutions of small, possibly rank-deficient contact systems,
// x = A^+ b, from a complete orthogonal decomposition. Eigen's own
// CompleteOrthogonalDecomposition::solve allocates temporaries on every call;
// this does the same operations, in the same order (so the same bits), in a
// workspace sized once.
#pragma once

#include "engine/contact/contact_data.hpp"
#include "engine/model.hpp"

namespace elbowsim {

// Solves with the m x m matrix that `ws.cod` has factorised (after
// ws.cod.compute(A) and ws.cod.setThreshold(...)): x [m] = A^+ b [m].
// Uses ws.work and ws.work_cols; x must not be one of them.
void min_norm_solve(SolverWorkspace& ws, ConstVec b, Eigen::Ref<Eigen::VectorXd> x);

// The contact forces of the p x p system c.A f = c.rhs (p = c.rows()) into
// c.fn, the rows of padded slots first made to prescribe their pads' forces
// (pad.hpp): Cholesky (LU with friction or pads, A is then not symmetric) while the
// smallest pivot stays above model.contact.rank_tolerance relative to the
// largest; below it the rows are dependent (c.dependent), and a complete
// orthogonal decomposition gives the minimum-norm f. Shared by every path
// that forms A (constrained_dynamics.hpp), so all give the same convention.
void rank_revealing_solve(const Model& model, ContactData& c);

}  // namespace elbowsim

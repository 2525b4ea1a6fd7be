// ABA's passes 2 and 3 with zero velocity and gravity, the articulated
// inertias known (aba.hpp): x = (M + Jm)^-1 tau for one or a few columns.
#include <algorithm>

#include "engine/dynamics/aba.hpp"

namespace elbowsim {

namespace {

// The last joint with a non-zero torque in column c (-1: none); beyond it the
// inward sweep would carry zeros.
int last_nonzero(const ResponseColumn& c, int n) {
  int last = n - 1;
  while (last >= 0 && c.tau[last * c.stride] == 0.0) --last;
  return last;
}

// M columns side by side. Inward: u_i = tau_i - S_i^T p_{i+1}, with p_{i+1} =
// sum_{k > i} (U_k / D_k) u_k the force the subtree passes to joint i;
// outward: x_i = u_i / D_i - (U_i / D_i)^T a_{i-1}, with a_{i-1} =
// sum_{k < i} S_k x_k. Each sweep is a serial chain; the neighbour's term is
// split off with e_i = S_i^T U_{i+1} / D_{i+1} (data.coupling, kept by the
// inward pass of the articulated inertias):
//   u_i = (tau_i - S_i^T p_{i+2}) - e_i u_{i+1},
//   x_i = (u_i / D_i - (U_i / D_i)^T a_{i-2}) - e_{i-1} x_{i-1},
// so a 6-dot waits for the joint before last and the chain from one joint to
// the next is one product and one subtraction. The columns' chains are
// independent, so the processor overlaps them too.
template <int M>
void sweep(const Model& model, const Data& data, const ResponseColumn* col) {
  const int n = model.dof;
  int last = -1;
  for (int c = 0; c < M; ++c) last = std::max(last, last_nonzero(col[c], n));
  for (int c = 0; c < M; ++c)
    for (int i = n - 1; i > last; --i) col[c].x[i] = 0.0;  // u = 0 there, p stays 0
  // p holds p_{i+2}, u_next u_{i+1} (zero beyond `last`).
  Eigen::Matrix<double, 6, M> p = Eigen::Matrix<double, 6, M>::Zero();
  double u_next[M] = {};
  for (int i = last; i >= 0; --i) {
    const Vector6d& S = data.motion_subspace[i];
    const double e = data.coupling[i];
    for (int c = 0; c < M; ++c) {
      const double u = (col[c].tau[i * col[c].stride] - S.dot(p.col(c))) - e * u_next[c];
      col[c].x[i] = u;
    }
    if (i + 1 <= last) {
      const Vector6d& Ud_next = data.U_over_D[i + 1];
      for (int c = 0; c < M; ++c) p.col(c) += Ud_next * u_next[c];
    }
    for (int c = 0; c < M; ++c) u_next[c] = col[c].x[i];
  }
  // a holds a_{i-2}, x_prev x_{i-1}.
  Eigen::Matrix<double, 6, M> a = Eigen::Matrix<double, 6, M>::Zero();
  double x_prev[M] = {};
  for (int i = 0; i < n; ++i) {
    const Vector6d& Ud = data.U_over_D[i];
    const double D_inv = data.D_inv[i];
    const double e = i > 0 ? data.coupling[i - 1] : 0.0;
    for (int c = 0; c < M; ++c) {
      const double x = (col[c].x[i] * D_inv - Ud.dot(a.col(c))) - e * x_prev[c];
      col[c].x[i] = x;
    }
    if (i > 0) {
      const Vector6d& S_prev = data.motion_subspace[i - 1];
      for (int c = 0; c < M; ++c) a.col(c) += S_prev * x_prev[c];
    }
    for (int c = 0; c < M; ++c) x_prev[c] = col[c].x[i];
  }
}

}  // namespace

void aba_responses(const Model& model, const Data& data, const ResponseColumn* columns, int m) {
  for (; m >= kResponseBatch; m -= kResponseBatch, columns += kResponseBatch)
    sweep<kResponseBatch>(model, data, columns);
  static_assert(kResponseBatch == 3, "the remainder below covers batches of 3");
  if (m == 2) sweep<2>(model, data, columns);
  if (m == 1) sweep<1>(model, data, columns);
}

void aba_response(const Model& model, const Data& data, ConstVec tau,
                  Eigen::Ref<Eigen::VectorXd> x) {
  const ResponseColumn column{tau.data(), tau.innerStride(), x.data()};
  sweep<1>(model, data, &column);
}

}  // namespace elbowsim

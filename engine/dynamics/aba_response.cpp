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

// M columns side by side. Inward: u_i = tau_i - S_i^T p, p += (U_i / D_i) u_i
// (p: the force the subtree passes to its parent); outward: x_i = u_i / D_i -
// (U_i / D_i)^T a, a += S_i x_i. The columns' chains are independent, so the
// processor overlaps them; 1 / D_i and U_i / D_i keep divisions off the chains.
template <int M>
void sweep(const Model& model, const Data& data, const ResponseColumn* col) {
  const int n = model.dof;
  int last = -1;
  for (int c = 0; c < M; ++c) last = std::max(last, last_nonzero(col[c], n));
  for (int c = 0; c < M; ++c)
    for (int i = n - 1; i > last; --i) col[c].x[i] = 0.0;  // u = 0 there, p stays 0
  Eigen::Matrix<double, 6, M> p = Eigen::Matrix<double, 6, M>::Zero();
  for (int i = last; i >= 0; --i) {
    const Vector6d& S = data.motion_subspace[i];
    const Vector6d& Ud = data.U_over_D[i];
    for (int c = 0; c < M; ++c) {
      const double u = col[c].tau[i * col[c].stride] - S.dot(p.col(c));
      col[c].x[i] = u;
      p.col(c) += Ud * u;
    }
  }
  Eigen::Matrix<double, 6, M> a = Eigen::Matrix<double, 6, M>::Zero();
  for (int i = 0; i < n; ++i) {
    const Vector6d& S = data.motion_subspace[i];
    const Vector6d& Ud = data.U_over_D[i];
    const double D_inv = data.D_inv[i];
    for (int c = 0; c < M; ++c) {
      const double x = col[c].x[i] * D_inv - Ud.dot(a.col(c));
      col[c].x[i] = x;
      a.col(c) += S * x;
    }
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

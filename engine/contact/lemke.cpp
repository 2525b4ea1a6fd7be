#include "engine/contact/lemke.hpp"

#include <algorithm>
#include <cmath>

namespace elbowsim {

LemkeScratch::LemkeScratch(int capacity)
    : inverse(Eigen::MatrixXd::Zero(capacity, capacity)),
      x(Eigen::VectorXd::Zero(capacity)),
      column(x),
      scaled(x),
      basis(static_cast<std::size_t>(capacity), 0) {}

namespace {

struct Tableau {
  const Eigen::Ref<const Eigen::MatrixXd>& M;
  int p;
  LemkeScratch& s;

  auto inverse() { return s.inverse.topLeftCorner(p, p); }
  auto x() { return s.x.head(p); }
  auto column() { return s.column.head(p); }

  // The column of variable v in the original system I w - M z - e z0 = q,
  // expressed in the current basis: B^-1 A_v, into s.column.
  void express(int v) {
    auto a = column();
    if (v < p) {
      a = inverse().col(v);
    } else if (v < 2 * p) {
      a.noalias() = -inverse() * M.col(v - p);
    } else {
      a = -inverse().rowwise().sum();
    }
  }

  // Lexicographic minimum ratio over rows with a_i > pivot: x_i / a_i first,
  // then the rows of B^-1 / a_i; the basic z0, if tied, leaves first.
  int ratio_test(double pivot) {
    int best = -1;
    for (int i = 0; i < p; ++i) {
      const double a = s.column[i];
      if (a <= pivot) continue;
      if (best < 0) {
        best = i;
        continue;
      }
      const double ab = s.column[best];
      const double ri = s.x[i] / a, rb = s.x[best] / ab;
      // Ratios equal up to rounding tie (degenerate problems, e.g. the zero q
      // of friction cones, give many): exact comparison would break the tie
      // by rounding, and Lemke's method could cycle or end on a false ray.
      const double diff = ri - rb, tie = 1e-12 * std::max({1.0, std::abs(ri), std::abs(rb)});
      if (diff < -tie) {
        best = i;
        continue;
      }
      if (diff > tie) continue;
      if (s.basis[i] == 2 * p) {
        best = i;
        continue;
      }
      if (s.basis[best] == 2 * p) continue;
      for (int k = 0; k < p; ++k) {
        const double d = s.inverse(i, k) / a - s.inverse(best, k) / ab;
        if (d < 0) {
          best = i;
          break;
        }
        if (d > 0) break;
      }
    }
    return best;
  }

  // Row r's variable leaves, the one expressed in s.column enters.
  void pivot(int r) {
    const double a = s.column[r];
    inverse().row(r) /= a;
    s.x[r] /= a;
    for (int i = 0; i < p; ++i) {
      if (i == r || s.column[i] == 0) continue;
      const double f = s.column[i];
      inverse().row(i) -= f * inverse().row(r);
      s.x[i] -= f * s.x[r];
    }
  }
};

}  // namespace

LemkeResult solve_lemke(const Eigen::Ref<const Eigen::MatrixXd>& M,
                        const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::Ref<Eigen::VectorXd> z,
                        Eigen::Ref<Eigen::VectorXd> w, LemkeScratch& s, double tolerance) {
  const int p = static_cast<int>(q.size());
  LemkeResult result;
  z.setZero();
  if (p == 0 || q.minCoeff() >= 0) {
    w = q;
    result.solved = true;
    return result;
  }
  Tableau t{M, p, s};
  t.inverse().setIdentity();
  t.x() = q;
  for (int i = 0; i < p; ++i) s.basis[i] = i;  // all w basic
  const double pivot_tolerance = tolerance * std::max(1.0, M.cwiseAbs().maxCoeff());
  // z0 enters at the most negative q: every x becomes >= 0.
  int r = 0;
  for (int i = 1; i < p; ++i)
    if (q[i] < q[r]) r = i;
  t.express(2 * p);
  t.pivot(r);
  int leaving = s.basis[r];
  s.basis[r] = 2 * p;
  const int max_pivots = 50 * (p + 1);
  for (result.pivots = 1; result.pivots < max_pivots; ++result.pivots) {
    // The complement of what left enters.
    const int entering = leaving < p ? leaving + p : leaving - p;
    t.express(entering);
    r = t.ratio_test(pivot_tolerance);
    if (r < 0) return result;  // ray termination
    t.pivot(r);
    leaving = s.basis[r];
    s.basis[r] = entering;
    if (leaving == 2 * p) {
      result.solved = true;
      break;
    }
  }
  if (!result.solved) return result;
  for (int i = 0; i < p; ++i)
    if (s.basis[i] >= p && s.basis[i] < 2 * p) z[s.basis[i] - p] = std::max(0.0, s.x[i]);
  w.noalias() = M * z;
  w += q;
  return result;
}

}  // namespace elbowsim

// One tolerance helper for every test: |a - b| <= atol + rtol |b|, elementwise.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace elbowsim::testing {

inline bool approx(double a, double b, double atol, double rtol = 0.0) {
  return std::abs(a - b) <= atol + rtol * std::abs(b);
}

template <typename A, typename B>
bool approx(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double atol,
            double rtol = 0.0) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  return ((a - b).cwiseAbs().array() <= atol + rtol * b.cwiseAbs().array()).all();
}

}  // namespace elbowsim::testing

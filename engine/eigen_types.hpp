// Eigen shorthands shared by the engine.
#pragma once

#include <Eigen/Core>
#include <cstring>

namespace elbowsim {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix3Xd = Eigen::Matrix<double, 3, Eigen::Dynamic>;
// Read-only view of a vector or of a segment of one, without copying.
using ConstVec = Eigen::Ref<const Eigen::VectorXd>;

// Whether a and b hold the same doubles bit for bit (a NaN never matches a
// number; -0 and +0 differ): the test for reusing a result computed from b.
inline bool same_bits(ConstVec a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}

}  // namespace elbowsim

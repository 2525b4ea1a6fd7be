// Eigen shorthands shared by the engine.
#pragma once

#include <Eigen/Core>

namespace elbowsim {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix3Xd = Eigen::Matrix<double, 3, Eigen::Dynamic>;
// Read-only view of a vector or of a segment of one, without copying.
using ConstVec = Eigen::Ref<const Eigen::VectorXd>;

}  // namespace elbowsim

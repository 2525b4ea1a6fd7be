// The textbook closed form of a 2-link planar arm's dynamics, the oracle of the
// inverse-dynamics and Walker-Orin tests.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "support/models.hpp"

namespace elbowsim::testing {

// Spong, Hutchinson & Vidyasagar, "Robot Modeling and Control", sec. 7.4.
// Angles from +x toward +z, gravity -z: heights are lc1 sin q1, etc.
struct TwoLinkClosedForm {
  double l1 = 0.4, lc1 = 0.17, lc2 = 0.21, m1 = 1.3, m2 = 0.8, I1 = 0.021, I2 = 0.013, g = 9.81;

  Eigen::Matrix2d M(const Eigen::Vector2d& q) const {
    const double c2 = std::cos(q[1]);
    Eigen::Matrix2d M;
    M(0, 0) = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2) + I1 + I2;
    M(0, 1) = M(1, 0) = m2 * (lc2 * lc2 + l1 * lc2 * c2) + I2;
    M(1, 1) = m2 * lc2 * lc2 + I2;
    return M;
  }
  Eigen::Vector2d coriolis(const Eigen::Vector2d& q, const Eigen::Vector2d& qd) const {
    const double h = -m2 * l1 * lc2 * std::sin(q[1]);
    return {h * (2 * qd[0] * qd[1] + qd[1] * qd[1]), -h * qd[0] * qd[0]};
  }
  Eigen::Vector2d gravity(const Eigen::Vector2d& q) const {
    const double c1 = std::cos(q[0]), c12 = std::cos(q[0] + q[1]);
    return {(m1 * lc1 + m2 * l1) * g * c1 + m2 * lc2 * g * c12, m2 * lc2 * g * c12};
  }
  Model model() const { return planar_arm({{l1, m1, lc1, I1}, {0.3, m2, lc2, I2}}); }
};

}  // namespace elbowsim::testing

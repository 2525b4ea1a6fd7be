// Small spatial-algebra helpers (Featherstone's notation). Spatial vectors are
// expressed in world coordinates at the world origin: motion [omega; v_O],
// force [moment_O; force].
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

// Spatial inertia at the world origin of a body with mass m, com c and
// rotational inertia Ic about the com: [[Ic + m cx cx^T, m cx], [m cx^T, m 1]].
inline Matrix6d spatial_inertia(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic) {
  const Eigen::Matrix3d C = skew(c);
  Matrix6d I;
  I.topLeftCorner<3, 3>() = Ic + m * C * C.transpose();
  I.topRightCorner<3, 3>() = m * C;
  I.bottomLeftCorner<3, 3>() = m * C.transpose();
  I.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  return I;
}

// I += spatial_inertia(m, c, Ic), written out: C C^T = (c.c) 1 - c c^T, so
// no 3 x 3 products and no temporary 6 x 6.
inline void add_spatial_inertia(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic,
                                Matrix6d& I) {
  const Eigen::Vector3d mc = m * c;
  const double mcc = mc.dot(c);
  I.topLeftCorner<3, 3>() += Ic - mc * c.transpose();
  I.topLeftCorner<3, 3>().diagonal().array() += mcc;
  // m C = m skew(c) (upper right), m C^T = -m skew(c) (lower left).
  I(0, 4) -= mc.z(); I(0, 5) += mc.y(); I(1, 3) += mc.z();
  I(1, 5) -= mc.x(); I(2, 3) -= mc.y(); I(2, 4) += mc.x();
  I(4, 0) -= mc.z(); I(5, 0) += mc.y(); I(3, 1) += mc.z();
  I(5, 1) -= mc.x(); I(3, 2) -= mc.y(); I(4, 2) += mc.x();
  I(3, 3) += m; I(4, 4) += m; I(5, 5) += m;
}

// Motion subspace of a revolute joint with unit axis z through point o.
inline Vector6d revolute_subspace(const Eigen::Vector3d& z, const Eigen::Vector3d& o) {
  Vector6d S;
  S << z, o.cross(z);
  return S;
}

// v x m (motion cross product).
inline Vector6d cross_motion(const Vector6d& v, const Vector6d& m) {
  Vector6d r;
  r << v.head<3>().cross(m.head<3>()),
      v.head<3>().cross(m.tail<3>()) + v.tail<3>().cross(m.head<3>());
  return r;
}

// v x* f (force cross product).
inline Vector6d cross_force(const Vector6d& v, const Vector6d& f) {
  Vector6d r;
  r << v.head<3>().cross(f.head<3>()) + v.tail<3>().cross(f.tail<3>()),
      v.head<3>().cross(f.tail<3>());
  return r;
}

}  // namespace elbowsim

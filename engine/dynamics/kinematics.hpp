// Forward kinematics of every link frame, point Jacobians and their Jdot*qd term.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Fills data.rotation/origin/axis/com/inertia (world) for the joint angles q [n].
void forward_kinematics(const Model& model, Data& data, ConstVec q);

// World position of `point` (link frame) on `link`. Needs forward_kinematics.
Eigen::Vector3d point_position(const Data& data, int link, const Eigen::Vector3d& point);

// Linear Jacobian (3 x n, world) of a point on a link: column j <= link is
// z_j x (r - o_j), the rest zero. Needs forward_kinematics. J is resized once.
void point_jacobian(const Model& model, const Data& data, int link, const Eigen::Vector3d& point,
                    Eigen::Ref<Matrix3Xd> J);

// The outward Newton-Euler pass with qdd = 0 over links 0 .. last: column i
// of omega, omega_dot and acc gets link i's angular velocity, angular
// acceleration and origin acceleration [world]. Needs forward_kinematics.
void outward_rates(const Data& data, int last, ConstVec qd, Eigen::Ref<Matrix3Xd> omega,
                   Eigen::Ref<Matrix3Xd> omega_dot, Eigen::Ref<Matrix3Xd> acc);

// dJ/dt * qd for the same point [m/s^2, world]: its acceleration when qdd = 0
// and gravity is off. Needs forward_kinematics.
Eigen::Vector3d point_jacobian_dot_qd(const Data& data, int link, const Eigen::Vector3d& point,
                                      ConstVec qd);

// World velocity of a point on a link [m/s] for joint rates qd.
Eigen::Vector3d point_velocity(const Data& data, int link, const Eigen::Vector3d& point,
                               ConstVec qd);

}  // namespace elbowsim

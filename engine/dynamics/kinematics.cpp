#include "engine/dynamics/kinematics.hpp"

#include <cmath>

namespace elbowsim {

void forward_kinematics(const Model& model, Data& data, ConstVec q) {
  if (data.kinematics_model == model.id && same_bits(q, data.kinematics_q)) return;
  Eigen::Matrix3d parent_rotation = model.base.linear();
  Eigen::Vector3d parent_origin = model.base.translation();
  for (int i = 0; i < model.dof; ++i) {
    const Joint& joint = model.joints[i];
    const JointRotation& r = model.joint_rotations[static_cast<std::size_t>(i)];
    const Link& link = model.links[i];
    // Link frame i = parent frame * fixed origin * rotation about the axis by
    // q_i, the last two by Rodrigues (model.hpp, JointRotation).
    const double c = std::cos(q[i]), s = std::sin(q[i]);
    const Eigen::Matrix3d local = r.fixed + c * r.cosine + s * r.sine;
    data.origin[i] = parent_origin + parent_rotation * joint.origin_position;
    data.rotation[i].noalias() = parent_rotation * local;
    data.axis[i].noalias() = parent_rotation * r.axis;  // the axis is fixed by its own rotation
    data.com[i] = data.origin[i] + data.rotation[i] * link.com;
    data.inertia[i] = data.rotation[i] * link.inertia * data.rotation[i].transpose();
    parent_rotation = data.rotation[i];
    parent_origin = data.origin[i];
  }
  data.kinematics_q = q;
  data.kinematics_model = model.id;
  ++data.kinematics_serial;
}

Eigen::Vector3d point_position(const Data& data, int link, const Eigen::Vector3d& point) {
  return data.origin[link] + data.rotation[link] * point;
}

void point_jacobian(const Model& model, const Data& data, int link, const Eigen::Vector3d& point,
                    Eigen::Ref<Matrix3Xd> J) {
  const Eigen::Vector3d r = point_position(data, link, point);
  for (int j = 0; j < model.dof; ++j) {
    if (j <= link)
      J.col(j) = data.axis[j].cross(r - data.origin[j]);
    else
      J.col(j).setZero();
  }
}

Eigen::Vector3d point_velocity(const Data& data, int link, const Eigen::Vector3d& point,
                               ConstVec qd) {
  const Eigen::Vector3d r = point_position(data, link, point);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int j = 0; j <= link; ++j) v += qd[j] * data.axis[j].cross(r - data.origin[j]);
  return v;
}

// Outward recursion of the Newton-Euler velocity/acceleration pass with
// qdd = 0: omega_i = omega_{i-1} + z_i qd_i, omegadot_i = omegadot_{i-1} +
// omega_{i-1} x z_i qd_i, and the origin acceleration carried along the links.
void outward_rates(const Data& data, int last, ConstVec qd, Eigen::Ref<Matrix3Xd> omega_out,
                   Eigen::Ref<Matrix3Xd> omega_dot_out, Eigen::Ref<Matrix3Xd> acc_out) {
  Eigen::Vector3d omega = Eigen::Vector3d::Zero(), omega_dot = Eigen::Vector3d::Zero();
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
  for (int i = 0; i <= last; ++i) {
    if (i > 0) {
      const Eigen::Vector3d d = data.origin[i] - data.origin[i - 1];
      acc += omega_dot.cross(d) + omega.cross(omega.cross(d));
    }
    const Eigen::Vector3d w_joint = data.axis[i] * qd[i];
    omega_dot += omega.cross(w_joint);
    omega += w_joint;
    omega_out.col(i) = omega;
    omega_dot_out.col(i) = omega_dot;
    acc_out.col(i) = acc;
  }
}

Eigen::Vector3d point_jacobian_dot_qd(const Data& data, int link, const Eigen::Vector3d& point,
                                      ConstVec qd) {
  Matrix3Xd omega(3, link + 1), omega_dot(3, link + 1), acc(3, link + 1);
  outward_rates(data, link, qd, omega, omega_dot, acc);
  const Eigen::Vector3d d = point_position(data, link, point) - data.origin[link];
  return acc.col(link) + omega_dot.col(link).cross(d) +
         omega.col(link).cross(omega.col(link).cross(d));
}

}  // namespace elbowsim

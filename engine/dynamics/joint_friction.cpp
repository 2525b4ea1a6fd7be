#include "engine/dynamics/joint_friction.hpp"

#include <cmath>

#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/walker_orin.hpp"

namespace elbowsim {

double sliding_friction(const JointFriction& f, double speed) {
  const double w = speed / f.stribeck_velocity;
  return f.coulomb + (f.breakaway - f.coulomb) * std::exp(-w * w);
}

bool any_joint_stuck(const Model& model, const Data& data) {
  if (!model.effects.joint_friction) return false;
  for (signed char mode : data.joint_mode)
    if (mode == 0) return true;
  return false;
}

void lock_stuck_joints(Data& data) {
  data.joint_mass = data.mass_matrix;
  for (Eigen::Index j = 0; j < data.joint_mass.rows(); ++j) {
    if (data.joint_mode[static_cast<std::size_t>(j)] != 0) continue;
    data.joint_mass.row(j).setZero();
    data.joint_mass.col(j).setZero();
    data.joint_mass(j, j) = 1.0;
  }
}

void sliding_friction_torques(const Model& model, Data& data, ConstVec qd) {
  for (int j = 0; j < model.dof; ++j) {
    const signed char mode = data.joint_mode[static_cast<std::size_t>(j)];
    data.joint_friction_torque[j] =
        mode == 0 ? 0.0 : -mode * sliding_friction(model.joint_friction[static_cast<std::size_t>(j)], std::abs(qd[j]));
  }
  data.tau_applied = data.actuation + data.joint_friction_torque;
}

void joint_friction_dynamics(const Model& model, Data& data, ConstVec qd) {
  if (!any_joint_stuck(model, data)) {
    forward_dynamics(model, data, qd, data.tau_applied, data.qdd);
    return;
  }
  // Locked joints: (M qdd)_F = (tau - B)_F with qdd_S = 0. M's stuck rows and
  // columns become the identity and their right-hand side 0, so one n x n
  // Cholesky (data.llt, no allocation) gives qdd_F and qdd_S = 0 exactly.
  mass_matrix_crba(model, data);
  bias_torques(model, data, qd);
  data.tau = data.tau_applied - data.bias;  // (tau - B), kept for the holding torques
  lock_stuck_joints(data);
  data.qdd = data.tau;
  for (int j = 0; j < model.dof; ++j)
    if (data.joint_mode[static_cast<std::size_t>(j)] == 0) data.qdd[j] = 0.0;
  data.llt.compute(data.joint_mass);
  data.llt.solveInPlace(data.qdd);
  // What holds a stuck joint: M_j qdd - (tau - B)_j (its friction torque).
  for (int j = 0; j < model.dof; ++j)
    if (data.joint_mode[static_cast<std::size_t>(j)] == 0)
      data.joint_friction_torque[j] = data.mass_matrix.row(j).dot(data.qdd) - data.tau[j];
}

void holding_torques(const Model& model, Data& data) {
  const ContactData& c = data.contact;
  for (int j = 0; j < model.dof; ++j) {
    if (data.joint_mode[static_cast<std::size_t>(j)] != 0) continue;
    data.joint_friction_torque[j] = data.mass_matrix.row(j).dot(data.qdd) -
                                    (data.tau_applied[j] - data.bias[j]) - c.Jf.col(j).dot(c.fn);
  }
}

}  // namespace elbowsim

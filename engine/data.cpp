#include "engine/data.hpp"

#include "engine/run/state_layout.hpp"

namespace elbowsim {

Data::Data(const Model& model) {
  const int n = model.dof;
  const auto un = static_cast<std::size_t>(n);
  q = qd = current = qdd = voltage = current_rate = actuation = Eigen::VectorXd::Zero(n);
  rotation.assign(un, Eigen::Matrix3d::Identity());
  origin.assign(un, Eigen::Vector3d::Zero());
  axis = com = omega = omega_dot = origin_acc = force = moment = origin;
  inertia = rotation;
  mass_matrix = Eigen::MatrixXd::Zero(n, n);
  llt = Eigen::LLT<Eigen::MatrixXd>(n);
  bias = tau = zero = unit = D = u = Eigen::VectorXd::Zero(n);
  spatial_inertia.assign(un, Matrix6d::Zero());
  articulated_inertia = spatial_inertia;
  motion_subspace.assign(un, Vector6d::Zero());
  velocity = bias_acc = bias_force = acc = U = motion_subspace;
  q_desired = qd_desired = v_feedforward = Eigen::VectorXd::Zero(n);
  const auto elbows = model.elbows.size();
  contact.resting.assign(elbows, false);
  contact.normal.assign(elbows, Eigen::Vector3d::UnitZ());
  contact.surface.assign(elbows, Eigen::Vector3d::Zero());
  contact.J3 = Matrix3Xd::Zero(3, n);
  contact.a_free = Eigen::VectorXd::Zero(n);
  const int m = StateLayout(model).size;
  x = x_start = k1 = k2 = k3 = k4 = x_a = x_b = x_c = Eigen::VectorXd::Zero(m);
  lambda = Eigen::ArrayXd::Zero(m);
  for (StepCoefficients* c : {&step, &partial})
    c->exp_h = c->exp_half = c->phi1_half = c->phi1_h = c->f1 = c->f2 = c->f3 = lambda;
}

}  // namespace elbowsim

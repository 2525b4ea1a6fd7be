#include "data.hpp"

namespace elbowsim {

namespace {
// Size of the integrator state x = [q; qd; i (full motor); E_in; E_joule; E_viscous].
int state_size(const Model& model) {
  return 2 * model.dof + (model.has_current_state() ? model.dof : 0) + 3;
}
}  // namespace

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
  const int m = state_size(model);
  x = x_stage = k1 = k2 = k3 = k4 = x_a = x_b = x_c = Eigen::VectorXd::Zero(m);
  lambda = exp_h = exp_half = phi1_half = phi1_h = f1 = f2 = f3 = Eigen::ArrayXd::Zero(m);
}

}  // namespace elbowsim

#include "engine/dynamics/forward_dynamics.hpp"

#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/walker_orin.hpp"

namespace elbowsim {

namespace {

// Eq. (50) solved for qdd: qdd = (M + Jm)^-1 (tau - B_J), by Cholesky.
void solve_with_mass_matrix(Data& data, ConstVec tau,
                            Eigen::Ref<Eigen::VectorXd> qdd) {
  data.llt.compute(data.mass_matrix);
  data.tau = tau - data.bias;
  qdd = data.tau;
  data.llt.solveInPlace(qdd);
}

}  // namespace

void forward_dynamics(const Model& model, Data& data, DynamicsMethod method,
                      ConstVec qd, ConstVec tau,
                      Eigen::Ref<Eigen::VectorXd> qdd) {
  switch (method) {
    case DynamicsMethod::walker_orin:
      mass_matrix_walker_orin(model, data);
      bias_torques(model, data, qd);
      solve_with_mass_matrix(data, tau, qdd);
      return;
    case DynamicsMethod::crba:
      mass_matrix_crba(model, data);
      bias_torques(model, data, qd);
      solve_with_mass_matrix(data, tau, qdd);
      return;
    case DynamicsMethod::aba:
      forward_dynamics_aba(model, data, qd, tau, qdd);
      return;
  }
}

void forward_dynamics(const Model& model, Data& data, ConstVec qd,
                      ConstVec tau, Eigen::Ref<Eigen::VectorXd> qdd) {
  forward_dynamics(model, data, model.options.dynamics, qd, tau, qdd);
}

}  // namespace elbowsim

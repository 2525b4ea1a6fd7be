#include "engine/dynamics/aba.hpp"

#include "engine/dynamics/spatial.hpp"
#include "engine/dynamics/springs.hpp"

namespace elbowsim {

namespace {

// Pass 1 (outward): spatial velocities, velocity-product accelerations c_i and
// bias forces p_i = v_i x* I_i v_i.
void velocity_pass(const Model& model, Data& data, ConstVec qd) {
  Vector6d v = Vector6d::Zero();
  for (int i = 0; i < model.dof; ++i) {
    const Vector6d S = revolute_subspace(data.axis[i], data.origin[i]);
    const Vector6d vj = S * qd[i];
    v += vj;
    data.motion_subspace[i] = S;
    data.velocity[i] = v;
    data.bias_acc[i] = cross_motion(v, vj);
    data.spatial_inertia[i] = spatial_inertia(model.links[i].mass, data.com[i], data.inertia[i]);
    data.articulated_inertia[i] = data.spatial_inertia[i];
    data.bias_force[i] = cross_force(v, data.spatial_inertia[i] * v);
  }
}

// Pass 2 (inward): articulated inertias and bias forces, each joint's motion
// projected out before handing the remainder to the parent.
void articulated_pass(const Model& model, Data& data, ConstVec qd,
                      ConstVec tau) {
  for (int i = model.dof - 1; i >= 0; --i) {
    const Vector6d& S = data.motion_subspace[i];
    data.U[i] = data.articulated_inertia[i] * S;
    data.D[i] = S.dot(data.U[i]) + (model.has_armature() ? model.armature[i] : 0.0);
    double u = tau[i] - S.dot(data.bias_force[i]);
    if (model.effects.damping) u -= model.viscous[i] * qd[i];
    data.u[i] = u;
    data.D_inv[i] = 1.0 / data.D[i];
    data.U_over_D[i] = data.U[i] / data.D[i];
    if (i == model.dof - 1) data.coupling[i] = 0.0;
    if (i == 0) continue;
    data.coupling[i - 1] = data.motion_subspace[i - 1].dot(data.U_over_D[i]);
    const Matrix6d Ia = data.articulated_inertia[i] - data.U[i] * data.U[i].transpose() / data.D[i];
    data.articulated_inertia[i - 1] += Ia;
    data.bias_force[i - 1] += data.bias_force[i] + Ia * data.bias_acc[i] + data.U[i] * (u / data.D[i]);
  }
}

// Pass 3 (outward): accelerations. Gravity is a fictitious base acceleration -g.
void acceleration_pass(const Model& model, Data& data, Eigen::Ref<Eigen::VectorXd> qdd) {
  Vector6d a = Vector6d::Zero();
  if (model.effects.gravity) a.tail<3>() = -model.gravity;
  for (int i = 0; i < model.dof; ++i) {
    a += data.bias_acc[i];
    qdd[i] = (data.u[i] - data.U[i].dot(a)) / data.D[i];
    a += data.motion_subspace[i] * qdd[i];
    data.acc[i] = a;
  }
}

}  // namespace

void forward_dynamics_aba(const Model& model, Data& data, ConstVec qd,
                          ConstVec tau, Eigen::Ref<Eigen::VectorXd> qdd) {
  velocity_pass(model, data, qd);
  if (model.has_springs()) {  // the springs' torque joins the applied torques
    data.tau = tau;
    add_spring_torques(model, data.kinematics_q, 1.0, data.tau);
    articulated_pass(model, data, qd, data.tau);
  } else {
    articulated_pass(model, data, qd, tau);
  }
  acceleration_pass(model, data, qdd);
}

}  // namespace elbowsim

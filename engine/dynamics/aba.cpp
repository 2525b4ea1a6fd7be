#include "engine/dynamics/aba.hpp"

#include "engine/dynamics/spatial.hpp"

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
    if (i == 0) continue;
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
  articulated_pass(model, data, qd, tau);
  acceleration_pass(model, data, qdd);
}

// Pass 2 alone (Featherstone's I^A_i): U_i = I^A_i S_i, D_i = S_i^T U_i + Jm_i,
// I^A_{i-1} = I_{i-1} + I^A_i - U_i U_i^T / D_i. One 6 x 6 accumulator serves
// the whole chain. The child's projection is applied to U_i as
//   U_i = (I_i + I^A_{i+1}) S_i - U_{i+1} ((U_{i+1} / D_{i+1})^T S_i)
// rather than to the matrix first: the product with S_i then does not wait for
// the child's division, which leaves a 6-dot, not a 6 x 6 update and product,
// on the chain from one joint to the next.
void articulated_inertias(const Model& model, Data& data) {
  // I^A_{i+1}, not yet projected. Kept in memory (Data's scratch), not in
  // registers: 36 doubles do not fit the 16 SSE registers, and the compiler's
  // register copies and spills of a local 6 x 6 doubled the instructions.
  Matrix6d& Ia = data.articulated_inertia[0];
  Ia.setZero();
  Vector6d U_child = Vector6d::Zero(), U_over_D_child = Vector6d::Zero();
  for (int i = model.dof - 1; i >= 0; --i) {
    const Vector6d S = revolute_subspace(data.axis[i], data.origin[i]);
    data.motion_subspace[i] = S;
    add_spatial_inertia(model.links[i].mass, data.com[i], data.inertia[i], Ia);
    // Ia S as a sum of columns: packet-wise adds, where Eigen's product of a
    // fixed 6 x 6 would take six horizontal row dots.
    const Vector6d W = Ia.col(0) * S[0] + Ia.col(1) * S[1] + Ia.col(2) * S[2] +
                       Ia.col(3) * S[3] + Ia.col(4) * S[4] + Ia.col(5) * S[5];
    const Vector6d U = W - U_child * U_over_D_child.dot(S);
    const double D = S.dot(U) + (model.has_armature() ? model.armature[i] : 0.0);
    // Now I^A_i; the last joint has no child to project, joint 0 no parent to pass it to.
    if (i > 0 && i < model.dof - 1) Ia.noalias() -= U_child * U_over_D_child.transpose();
    const double D_inv = 1.0 / D;
    const Vector6d U_over_D = U * D_inv;
    data.U[i] = U;
    data.D[i] = D;
    data.D_inv[i] = D_inv;
    data.U_over_D[i] = U_over_D;
    U_child = U;
    U_over_D_child = U_over_D;
  }
}

}  // namespace elbowsim

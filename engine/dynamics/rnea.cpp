#include "engine/dynamics/rnea.hpp"

#include "engine/dynamics/springs.hpp"

namespace elbowsim {

namespace {

// Outward pass: angular velocity/acceleration of each link and the linear
// acceleration of its joint origin. Gravity enters as a base acceleration -g.
void outward_pass(const Model& model, Data& data, ConstVec qd,
                  ConstVec qdd, InverseDynamicsTerms terms) {
  Eigen::Vector3d omega = Eigen::Vector3d::Zero(), omega_dot = Eigen::Vector3d::Zero();
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
  if (terms.gravity && model.effects.gravity) acc = -model.gravity;
  for (int i = 0; i < model.dof; ++i) {
    if (i > 0) {
      const Eigen::Vector3d d = data.origin[i] - data.origin[i - 1];
      acc += omega_dot.cross(d);
      if (terms.velocity) acc += omega.cross(omega.cross(d));
    }
    omega_dot += data.axis[i] * qdd[i];
    if (terms.velocity) {
      const Eigen::Vector3d w_joint = data.axis[i] * qd[i];
      omega_dot += omega.cross(w_joint);
      omega += w_joint;
    }
    data.omega[i] = omega;
    data.omega_dot[i] = omega_dot;
    data.origin_acc[i] = acc;
  }
}

// Inward pass: force and moment (about the joint origin) that link i-1 exerts
// on link i; the joint torque is the moment's component along the axis.
void inward_pass(const Model& model, Data& data, Eigen::Ref<Eigen::VectorXd> tau) {
  Eigen::Vector3d f_child = Eigen::Vector3d::Zero(), n_child = Eigen::Vector3d::Zero();
  for (int i = model.dof - 1; i >= 0; --i) {
    const Eigen::Vector3d c = data.com[i] - data.origin[i];
    const Eigen::Vector3d& w = data.omega[i];
    const Eigen::Vector3d a_com =
        data.origin_acc[i] + data.omega_dot[i].cross(c) + w.cross(w.cross(c));
    const Eigen::Vector3d F = model.links[i].mass * a_com;
    const Eigen::Vector3d N = data.inertia[i] * data.omega_dot[i] + w.cross(data.inertia[i] * w);
    Eigen::Vector3d n = N + c.cross(F) + n_child;
    if (i + 1 < model.dof) n += (data.origin[i + 1] - data.origin[i]).cross(f_child);
    f_child = F + f_child;
    n_child = n;
    data.force[i] = f_child;
    data.moment[i] = n;
    tau[i] = data.axis[i].dot(n);
  }
}

}  // namespace

void inverse_dynamics(const Model& model, Data& data, ConstVec qd,
                      ConstVec qdd, InverseDynamicsTerms terms,
                      Eigen::Ref<Eigen::VectorXd> tau) {
  data.bias_rates_serial = -1;  // bias_torques() stamps them again
  outward_pass(model, data, qd, qdd, terms);
  inward_pass(model, data, tau);
  // Motor-reflected terms of eq. (51): Jm qdd + (D + Dm) qd.
  if (model.has_armature()) tau += model.armature.cwiseProduct(qdd);
  if (terms.damping && model.effects.damping) tau += model.viscous.cwiseProduct(qd);
  if (terms.springs) add_spring_torques(model, data.kinematics_q, -1.0, tau);
}

}  // namespace elbowsim

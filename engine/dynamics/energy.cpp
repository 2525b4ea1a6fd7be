#include "engine/dynamics/energy.hpp"

#include "engine/dynamics/springs.hpp"

namespace elbowsim {

namespace {

// 1/2 sum (m |v_c|^2 + w^T I w), with link velocities from an outward pass.
double link_kinetic_energy(const Model& model, const Data& data, ConstVec qd) {
  Eigen::Vector3d omega = Eigen::Vector3d::Zero(), v_origin = Eigen::Vector3d::Zero();
  double energy = 0;
  for (int i = 0; i < model.dof; ++i) {
    if (i > 0) v_origin += omega.cross(data.origin[i] - data.origin[i - 1]);
    omega += data.axis[i] * qd[i];
    const Eigen::Vector3d v_com = v_origin + omega.cross(data.com[i] - data.origin[i]);
    energy += 0.5 * (model.links[i].mass * v_com.squaredNorm() + omega.dot(data.inertia[i] * omega));
  }
  return energy;
}

}  // namespace

void stored_energy(const Model& model, const Data& data, ConstVec qd, ConstVec current,
                   EnergyTerms& out) {
  out.kinetic_links = link_kinetic_energy(model, data, qd);
  out.kinetic_rotors = model.has_armature() ? 0.5 * qd.dot(model.armature.cwiseProduct(qd)) : 0.0;
  out.potential = 0;
  if (model.effects.gravity)
    for (int i = 0; i < model.dof; ++i)
      out.potential -= model.links[i].mass * model.gravity.dot(data.com[i]);
  out.spring = model.has_springs() ? spring_energy(model, data.kinematics_q) : 0.0;
  out.magnetic = model.has_current_state()
                     ? 0.5 * current.dot(model.inductance.cwiseProduct(current))
                     : 0.0;
}

double balance_residual(const EnergyTerms& now, const EnergyTerms& initial) {
  const double supplied = energy_sum(now, EnergyRole::supplied);
  const double lost = energy_sum(now, EnergyRole::lost);
  return supplied - lost - (now.stored() - initial.stored());
}

}  // namespace elbowsim

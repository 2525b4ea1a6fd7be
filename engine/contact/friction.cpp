#include "engine/contact/friction.hpp"

#include <cmath>

#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

int tangent_basis(const Model& model, const Eigen::Vector3d& n, Eigen::Vector3d& t1,
                  Eigen::Vector3d& t2) {
  const Eigen::Vector3d& axis = model.planar_axis;
  if (axis.squaredNorm() > 0 && std::abs(axis.dot(n)) < 1e-9) {
    t1 = axis.cross(n).normalized();
    t2.setZero();
    return 1;
  }
  // A reference that is never parallel to n: the world axis least aligned with it.
  Eigen::Index least = 0;
  n.cwiseAbs().minCoeff(&least);
  t1 = n.cross(Eigen::Vector3d::Unit(least)).normalized();
  t2 = n.cross(t1);
  return 2;
}

Eigen::Vector3d contact_point_local(const Data& data, int slot, const Eigen::Vector3d& n) {
  const Primitive& p = data.contact.primitive_of(slot);
  const Eigen::Vector3d& centre = data.contact.detected[slot].local;
  return centre - p.radius * (data.rotation[p.link].transpose() * n);
}

Eigen::Vector3d tangential_velocity(const Data& data, int slot, const Eigen::Vector3d& n, ConstVec qd) {
  const int link = data.contact.primitive_of(slot).link;
  const Eigen::Vector3d v = point_velocity(data, link, contact_point_local(data, slot, n), qd);
  return v - n * n.dot(v);
}

double friction_scale(const FrictionOptions& friction, double speed) {
  switch (friction.law) {
    case FrictionLaw::coulomb: return 1.0;
    case FrictionLaw::tanh: return std::tanh(speed / friction.tanh_velocity);
    case FrictionLaw::saturated: return speed / std::max(speed, friction.slip_velocity);
  }
  return 1.0;
}

}  // namespace elbowsim

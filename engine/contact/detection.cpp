#include "engine/contact/detection.hpp"

#include "engine/contact/collision.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/state_layout.hpp"

namespace elbowsim {

void detect_contacts(const Model& model, Data& data) {
  const StateLayout s(model);
  ContactData& c = data.contact;
  forward_kinematics(model, data, data.x.segment(s.q(), s.n));
  c.world->elbow_contacts(model, data, c.detected);
  for (std::size_t k = 0; k < c.detected.size(); ++k) {
    c.normal[k] = c.detected[k].normal;
    c.surface[k] = c.detected[k].point;
  }
}

double normal_speed(const Model& model, const Data& data, int elbow) {
  const StateLayout s(model);
  const Elbow& e = model.elbows[elbow];
  const Eigen::Vector3d v = point_velocity(data, e.link, e.point, data.x.segment(s.qd(), s.n));
  return data.contact.normal[elbow].dot(v);
}

}  // namespace elbowsim

// engine/data.cpp: a Data sized once from its model, and check_data refusing a Data made
// for another model, naming what differs.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "engine/data.hpp"
#include "engine/state_layout.hpp"
#include "support/models.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The message of check_data's invalid_argument, or "" when it accepts.
std::string refusal(const Model& model, const Data& data) {
  try {
    check_data(model, data);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Data: every member sized from the model, the model's id, dof and state size kept") {
  Model m = driven_arm(IntegratorKind::rk4, 1e-3, 1.0, 0.5e-3);
  m.elbows = {Elbow{"a", 0, Eigen::Vector3d(0.2, 0, 0), 0.03}, Elbow{"b", 1, Eigen::Vector3d(0.1, 0, 0), 0.03}};
  m.table = {TableBox{}, TableBox{}, TableBox{}};
  m.effects.contact = true;
  finalize(m);
  const Data data(m);
  CHECK(data.model_id == m.id);
  CHECK(data.dof == 2);
  CHECK(data.state_size == StateLayout(m).size);
  CHECK(data.x.size() == StateLayout(m).size);
  for (const Eigen::VectorXd* v : {&data.q, &data.qd, &data.current, &data.qdd, &data.voltage,
                                   &data.actuation, &data.bias, &data.q_desired, &data.v_feedforward})
    CHECK(v->size() == 2);
  CHECK((data.mass_matrix.rows() == 2 && data.mass_matrix.cols() == 2));
  CHECK(data.rotation.size() == 2);
  CHECK(data.spatial_inertia.size() == 2);
  // Slots: 2 elbows x 3 boxes, and the 2 links' capsules (their shared joint ball
  // once) x 3 boxes x (ends and interior).
  CHECK(data.contact.slots() == data.contact.geometry.slots.size());
  CHECK(data.contact.resting.size() == data.contact.geometry.slots.size());
  CHECK(data.contact.geometry.primitives.size() == 4);
  CHECK(data.contact.primitive_of(0).elbow == 0);
  // The step's lists are reserved: a landing and a release per slot and stage.
  CHECK(data.log.events.capacity() >= 4 * data.contact.geometry.slots.size());
  CHECK(data.log.warnings.capacity() >= 1);
  CHECK_NOTHROW(check_data(m, data));
}

TEST_CASE("check_data names what differs: model id, dof, state size, elbows") {
  const Model m = pendulum(IntegratorKind::rk4, 1e-3, 0.1);
  const Data data(m);
  CHECK(refusal(m, data).empty());

  Model other = m;  // the same model, finalized anew: another id
  finalize(other);
  std::string message = refusal(other, data);
  MESSAGE(message);
  CHECK(message.find("model id " + std::to_string(m.id) + " (Data) vs " + std::to_string(other.id)) !=
        std::string::npos);
  CHECK(message.find("model 'planar_arm'") != std::string::npos);

  // Changed in place (same id, so only the later checks can tell).
  Model more_joints = m;
  more_joints.dof = 3;
  message = refusal(more_joints, data);
  CHECK(message.find("dof 2 (Data) vs 3") != std::string::npos);

  Model with_currents = m;
  with_currents.effects.motor = MotorModel::full;
  message = refusal(with_currents, data);
  CHECK(message.find("state size " + std::to_string(data.state_size) + " (Data) vs " +
                     std::to_string(StateLayout(with_currents).size)) != std::string::npos);

  Model with_elbow = m;
  with_elbow.elbows.push_back(Elbow{"e", 0, Eigen::Vector3d::Zero(), 0.03});
  message = refusal(with_elbow, data);
  CHECK(message.find("elbows 0 (Data) vs 1") != std::string::npos);
}

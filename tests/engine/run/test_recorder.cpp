// engine/run/recorder.cpp: the layout of a run and record_sample writing every column of
// it from Data (a scene with motors, a hand task and an elbow on the table).
#include <doctest/doctest.h>

#include <cmath>

#include "engine/control/plan.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/recorder.hpp"
#include "engine/run/step.hpp"
#include "support/approx.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The writing arm, elbow on the table, PD + feed-forward on full motors, 50 ms.
ExperimentScene short_run() {
  WritingArm arm;
  arm.run_duration = 0.05;
  return arm.scene();
}

}  // namespace

TEST_CASE("trajectory_layout: the groups of the model's effects, elbows only with contact") {
  const ExperimentScene s = short_run();
  const TrajectoryLayout with = trajectory_layout(s.model, true);
  CHECK(with.dof() == 4);
  CHECK(with.has_motors());
  CHECK(with.has_desired_hand());
  CHECK(with.has_contact());
  CHECK(with.groups().elbows == std::vector<std::string>{"elbow"});
  Model off = s.model;
  off.effects.contact = false;
  off.effects.motor = MotorModel::none;
  finalize(off);
  const TrajectoryLayout without = trajectory_layout(off, false);
  CHECK_FALSE(without.has_motors());
  CHECK_FALSE(without.has_desired_hand());
  CHECK_FALSE(without.has_contact());
  CHECK(without.elbows() == 0);  // the model's elbows are not recorded without contact
}

TEST_CASE("record_sample writes every column (no NaN left) from Data, column by column") {
  const ExperimentScene s = short_run();
  const Model& m = s.model;
  Data data(m);
  data.controller = make_controller(m, s.experiment);
  reset(m, data);
  Recording rec(trajectory_layout(m, true));
  record_sample(m, data, rec);
  for (int k = 0; k < 20; ++k) step(m, data);
  REQUIRE_FALSE(data.failure);
  evaluate_outputs(m, data);
  record_sample(m, data, rec);
  REQUIRE(rec.rows() == 2);
  const TrajectoryLayout& L = rec.layout;
  for (std::size_t row = 0; row < 2; ++row)
    for (int c = 0; c < L.size(); ++c) {
      CAPTURE(row);
      CAPTURE(rec.columns()[std::size_t(c)].name);
      CHECK(std::isfinite(rec.at(row, std::size_t(c))));
    }
  // The last row is the state in data, each value in its named column.
  const auto at = [&](int column) { return rec.at(1, std::size_t(column)); };
  CHECK(at(L.time()) == data.t);
  for (int j = 0; j < 4; ++j) {
    CAPTURE(j);
    CHECK(at(L.q(j)) == data.q[j]);
    CHECK(at(L.qd(j)) == data.qd[j]);
    CHECK(at(L.qdd(j)) == data.qdd[j]);
    CHECK(at(L.current(j)) == data.current[j]);
    CHECK(at(L.voltage(j)) == data.voltage[j]);
    CHECK(at(L.torque(j)) == data.actuation[j]);
  }
  forward_kinematics(m, data, data.q);
  const Eigen::Vector3d hand = point_position(data, m.hand_link, m.hand_point);
  const Eigen::Vector3d desired = data.controller->plan->hand_at(data.t);
  for (int a = 0; a < 3; ++a) {
    CHECK(at(L.hand(a)) == hand[a]);
    CHECK(at(L.hand_desired(a)) == desired[a]);
  }
  CHECK(at(L.hand_error()) == (hand - desired).norm());
  REQUIRE(data.contact.active == std::vector<int>{0});
  CHECK(at(L.elbow_force(0)) == data.contact.fn[0]);
  CHECK(at(L.elbow_force(0)) > 0);  // the arm leans on its elbow
  CHECK(at(L.elbow_distance(0)) == data.contact.detected[0].distance);
  CHECK(at(L.elbow_resting(0)) == 1.0);
  CHECK(at(L.energy(Energy::electrical_in)) == data.energy.electrical_in);
  CHECK(at(L.energy(Energy::magnetic)) == data.energy.magnetic);
  CHECK(at(L.energy(Energy::normal_work)) == data.energy.normal_work);
  CHECK(at(L.balance_residual()) == balance_residual(data.energy, data.energy_initial));
}

// engine/run/active_set.cpp: which elbows rest for the coming step (the LCP on the
// touching elbows), select_active_set on its own: landings, releases, Painleve's paradox
// and dependent rows; and Painleve's paradox stopping a whole run.
#include <doctest/doctest.h>

#include <cmath>

#include <numbers>

#include "engine/contact/collision.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/detection.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/active_set.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The sliding arm with friction mu = 3 A / B, where A = Jc M^-1 Jc^T and B = Jc M^-1 Jt^T:
// sliding the way friction pushes the elbow down, the Delassus "matrix" A - mu B of the
// resting elbow is negative, Painleve's paradox. Its initial rates slide the elbow along
// the table (qd in the null space of Jc).
Model painleve_scene() {
  Model m = sliding_arm(Stabilization::baumgarte, 0.2, 1e-3);
  m.effects.friction = true;
  m.contact.friction.mu = 1.0;
  finalize(m);
  Data data(m);
  reset_state(m, data);
  const Eigen::VectorXd q = m.initial.q;
  forward_kinematics(m, data, q);
  data.contact.active = {0};
  data.contact.normal[0] = Eigen::Vector3d::UnitZ();
  // A sliding motion that keeps the elbow on the table: qd in the null space of Jc.
  Eigen::VectorXd qd = Eigen::Vector3d(1, 0, 0);
  constraint_rows(m, data, qd);
  const Eigen::RowVectorXd Jc = data.contact.Jc.row(0);
  qd -= Jc.transpose() * (Jc * qd) / Jc.squaredNorm();
  constraint_rows(m, data, qd);
  mass_matrix_crba(m, data);
  data.llt.compute(data.mass_matrix);
  const Eigen::RowVectorXd Jt = data.contact.Jc.row(0) - data.contact.Jf.row(0);  // mu = 1
  const double A = Jc * data.llt.solve(Jc.transpose());
  double B = Jc * data.llt.solve(Jt.transpose());
  if (B < 0) qd = -qd, B = -B;  // slide the way friction pushes the elbow down
  REQUIRE(B > 0);
  m.contact.friction.mu = 3.0 * A / B;
  m.initial.qd = qd;
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("select_active_set: a touching elbow the arm presses down becomes active, a landing") {
  // The elbow arm at its resting pose (distance 0), the shoulder carrying half of its
  // gravity torque: the table must push, so the LCP switches the row on.
  const ElbowArm arm;
  const Model m = arm.model(0.5 * arm.G1(), 0.0);
  Data data(m);
  place(m, data, Eigen::Vector2d(arm.q1, arm.q2), Eigen::Vector2d::Zero(), 0.25);
  REQUIRE(data.contact.resting[0] == 0);
  CHECK(select_active_set(m, data));
  CHECK(data.contact.active == std::vector<int>{0});
  CHECK(data.contact.resting[0] == 1);
  REQUIRE(data.log.events.size() == 1);
  const ContactEvent& e = data.log.events[0];
  CHECK(e.kind == ContactEvent::Kind::landing);
  CHECK(e.slot == 0);
  CHECK(e.t == 0.25);
  CHECK(e.speed == 0.0);  // at rest: no approach speed
  CHECK_FALSE(data.failure);
}

TEST_CASE("select_active_set: a resting elbow pressed into the table stays active, no event") {
  // The arm pushes down (half its gravity torque held) with the elbow 0.1 um into the
  // table, as drift leaves it: the row stays on.
  const ElbowArm arm;
  const Model m = arm.model(0.5 * arm.G1(), 0.0);
  Data data(m);
  const double into = 1e-7 / (arm.l1 * std::cos(arm.q1));
  place(m, data, Eigen::Vector2d(arm.q1 - into, arm.q2), Eigen::Vector2d::Zero(), 0.25);
  data.contact.resting[0] = 1;
  for (int call = 0; call < 3; ++call) {
    CHECK(select_active_set(m, data));
    CHECK(data.contact.active == std::vector<int>{0});
    CHECK(data.contact.resting[0] == 1);
  }
  CHECK(data.contact.detected[0].distance < 0);
  CHECK(data.log.events.empty());
  CHECK(data.log.warnings.empty());
}

TEST_CASE("select_active_set: a resting elbow its torques pull up is released, a release event") {
  // tau1 = 1.5 G1: the statics force (G1 - tau1)/(l1 cos q1) would be negative, so the
  // table cannot hold the elbow down; the LCP leaves the row off.
  const ElbowArm arm;
  REQUIRE(arm.statics_force(1.5 * arm.G1()) < 0);
  const Model m = arm.model(1.5 * arm.G1(), 0.0);
  Data data(m);
  place(m, data, Eigen::Vector2d(arm.q1, arm.q2), Eigen::Vector2d::Zero(), 0.4);
  data.contact.resting[0] = 1;
  CHECK(select_active_set(m, data));
  CHECK(data.contact.active.empty());
  CHECK(data.contact.resting[0] == 0);
  REQUIRE(data.log.events.size() == 1);
  CHECK(data.log.events[0].kind == ContactEvent::Kind::release);
  CHECK(data.log.events[0].slot == 0);
  CHECK(data.log.events[0].t == 0.4);
}

TEST_CASE("select_active_set: a touching approaching elbow lands at its speed; separating or above, not") {
  const ElbowArm arm;
  const Model m = arm.model(0.5 * arm.G1(), 0.0);
  SUBCASE("approaching: active, landing event with the approach speed") {
    Data data(m);
    place(m, data, Eigen::Vector2d(arm.q1, arm.q2), Eigen::Vector2d(-0.2, 0.1), 0.0);
    CHECK(select_active_set(m, data));
    const double v = normal_speed(m, data, 0);
    REQUIRE(v < -1e-3);
    CHECK(data.contact.active == std::vector<int>{0});
    REQUIRE(data.log.events.size() == 1);
    CHECK(data.log.events[0].kind == ContactEvent::Kind::landing);
    CHECK(data.log.events[0].speed == -v);  // > 0: the approach speed
  }
  SUBCASE("separating faster than separation_velocity: not a candidate") {
    Data data(m);
    place(m, data, Eigen::Vector2d(arm.q1, arm.q2), Eigen::Vector2d(0.2, 0.0), 0.0);
    CHECK(select_active_set(m, data));
    CHECK(normal_speed(m, data, 0) > m.contact.separation_velocity);
    CHECK(data.contact.active.empty());
    CHECK(data.log.events.empty());
  }
  SUBCASE("1 mm above the table, further than touch_distance: not a candidate") {
    Data data(m);
    const double up = 1e-3 / (arm.l1 * std::cos(arm.q1));
    place(m, data, Eigen::Vector2d(arm.q1 + up, arm.q2), Eigen::Vector2d(-0.2, 0.0), 0.0);
    CHECK(select_active_set(m, data));
    CHECK(data.contact.detected[0].distance > m.contact.touch_distance);
    CHECK(data.contact.active.empty());
    CHECK(data.log.events.empty());
  }
}

TEST_CASE("select_active_set: Painleve's configuration fails with data.failure = painleve") {
  const Model m = painleve_scene();
  Data data(m);
  place(m, data, m.initial.q, m.initial.qd, 0.125);
  data.step_count = 7;
  CHECK_FALSE(select_active_set(m, data));
  CHECK(data.failure.kind == Failure::Kind::painleve);
  CHECK(data.failure.t == 0.125);
  CHECK(data.failure.step == 7);
  // Without friction the same state is an ordinary resting elbow.
  Model frictionless = m;
  frictionless.effects.friction = false;
  finalize(frictionless);
  Data plain(frictionless);
  place(frictionless, plain, m.initial.q, m.initial.qd, 0.125);
  CHECK(select_active_set(frictionless, plain));
  CHECK_FALSE(plain.failure);
}

TEST_CASE("select_active_set: two elbows at one point warn once (2 rows of rank 1), count every step") {
  const ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), 0.0);
  m.elbows.push_back({"twin", 0, m.elbows[0].point, arm.r});
  finalize(m);
  Data data(m);
  place(m, data, Eigen::Vector2d(arm.q1, arm.q2), Eigen::Vector2d::Zero(), 0.0);
  CHECK(select_active_set(m, data));
  REQUIRE(data.log.warnings.size() == 1);
  CHECK(data.log.warnings[0].kind == Warning::Kind::dependent_rows);
  CHECK(data.log.warnings[0].count == 2);
  CHECK(data.log.warnings[0].rank == 1);
  CHECK(data.contact.dependent_steps == 1);
  data.log.clear();
  CHECK(select_active_set(m, data));
  CHECK(data.log.warnings.empty());  // once per run
  CHECK(data.contact.dependent_steps == 2);
  CHECK(data.contact.active.size() == 2);  // the minimum-norm split keeps both on
}

TEST_CASE("friction: high mu in a Painleve configuration stops with a clear message") {
  const Model m = painleve_scene();
  const RunResult r = simulate(m, {});
  CHECK_FALSE(r.completed);
  MESSAGE(r.failure);
  CHECK(r.failure.find("Painleve") != std::string::npos);
  CHECK(r.failure.find("t = 0") != std::string::npos);
}

namespace {

// A passive 3-link arm (no motors), joint damping, over a table whose top is
// one link radius below the shoulder: lying flat (q = 0) it rests on it.
//
//   o---o---o---o   (q = 0, on the table)
//   =================
Model passive_arm(double step) {
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.008}, {0.25, 0.8, 0.125, 0.004}, {0.2, 0.5, 0.1, 0.002}});
  TableBox top;
  top.center = Eigen::Vector3d(0.45, 0, -0.02 - 0.05);
  top.size = Eigen::Vector3d(1.1, 0.6, 0.1);
  m.table = {top};
  m.effects.contact = true;
  m.effects.damping = true;
  m.damping = Eigen::Vector3d::Constant(0.3);
  m.initial.q = Eigen::Vector3d(0.3, -0.1, -0.1);
  m.options = {4.0, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("a passive 3-link arm dropped on the table settles lying on it: statics G(q) = Jc^T f") {
  const Model m = passive_arm(1e-3);
  const RunResult r = simulate(m, RunOptions{100, {}});
  INFO(r.failure);
  REQUIRE(r.valid);  // no link ever deeper than penetration_tolerance
  int landings = 0;
  for (const ContactEvent& e : r.events) landings += e.kind == ContactEvent::Kind::landing;
  CHECK(landings >= 3);  // each link's tip lands
  // At rest at the end: the links lie flat, and the table's forces balance gravity.
  Data data(m);
  const Recording& rec = r.trajectory;
  const std::size_t last = rec.rows() - 1;
  Eigen::VectorXd q(3), qd(3);
  for (int j = 0; j < 3; ++j) q[j] = rec.at(last, rec.layout.q(j)), qd[j] = rec.at(last, rec.layout.qd(j));
  CHECK(q.cwiseAbs().maxCoeff() < 1e-9);
  CHECK(qd.cwiseAbs().maxCoeff() < 1e-9);
  data.x.setZero();
  data.x.head(3) = q;
  reset_state(m, data);
  data.x.head(3) = q;
  data.contact.world = std::make_shared<CollisionWorld>(m, data.contact.geometry);
  REQUIRE(select_active_set(m, data));
  REQUIRE(data.contact.rows() >= 2);
  evaluate_outputs(m, data);
  Eigen::VectorXd gravity(3);
  inverse_dynamics(m, data, data.zero, data.zero, {false, true, false}, gravity);
  const Eigen::VectorXd table = data.contact.Jc.transpose() * data.contact.fn;
  MESSAGE("G(q) = ", gravity.transpose(), " N m, Jc^T f = ", table.transpose(), " N m with ",
          data.contact.rows(), " rows");
  CHECK((gravity - table).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("a capsule lying flat rests on two rows and neither sinks nor turns into the table in 10 s") {
  //   o shoulder
  //    \  link 0 down at 45 deg (0.3 m): its tip can move down, so both ends of
  //     o===== link 1 (0.4 m) lying flat on the table rest on rows
  //   ==================  top 2 cm (the radius) below the forearm's axis
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.008}, {0.4, 0.8, 0.2, 0.011}});
  const double elbow_z = -0.3 * std::sqrt(0.5);
  TableBox top;
  top.center = Eigen::Vector3d(0.4, 0, elbow_z - 0.02 - 0.05);
  top.size = Eigen::Vector3d(1.0, 0.6, 0.1);
  m.table = {top};
  m.effects.contact = true;
  m.initial.q = Eigen::Vector2d(-std::numbers::pi / 4, std::numbers::pi / 4);
  m.options = {10.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  Data data(m);
  reset(m, data);
  CHECK(data.contact.rows() == 2);  // both ends of the forearm: link 0's tip ball, link 1's tip
  const RunResult r = simulate(m, RunOptions{100, {}});
  INFO(r.failure);
  REQUIRE(r.valid);
  const Recording& rec = r.trajectory;
  double worst_angle = 0, worst_d = 0;
  for (std::size_t row = 0; row < rec.rows(); ++row) {
    const double forearm = rec.at(row, rec.layout.q(0)) + rec.at(row, rec.layout.q(1));
    worst_angle = std::max(worst_angle, std::abs(forearm));
    worst_d = std::max(worst_d, std::abs(rec.at(row, rec.layout.link_distance(1))));
  }
  MESSAGE("over 10 s: forearm angle within ", worst_angle, " rad, its clearance within ", worst_d, " m");
  // Held by Baumgarte-stabilised rows: rounding, not drift.
  CHECK(worst_angle < 1e-9);
  CHECK(worst_d < 1e-9);
}

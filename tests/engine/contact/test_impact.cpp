// engine/contact/impact.cpp: the impact law (Newton restitution on the Delassus
// matrix), apply_impact and the impact stage land_touching_slots on their own.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/detection.hpp"
#include "engine/contact/friction.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/contact/impact.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/step.hpp"
#include "engine/state_layout.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The falling elbow arm with its elbow `below` m under the table top (negative: above),
// moving with rates qd, at t = 0.123 s; detection done.
Data elbow_at_table(const Model& m, double below, const Eigen::Vector2d& qd) {
  const ElbowArm arm;
  Data data(m);
  const double dq = below / (arm.l1 * std::cos(arm.q1));
  place(m, data, Eigen::Vector2d(arm.q1 - dq, arm.q2), qd, 0.123);
  detect_contacts(m, data);
  return data;
}

}  // namespace

TEST_CASE("impact: plastic leaves zero normal speed, restitution e reverses e times it; KE loss == impulse formula") {
  for (double e : {0.0, 0.5}) {
    Model m = falling_arm(0.0, EventTiming::step, 1e-3, e);
    Data data(m);
    reset_state(m, data);
    data.x.segment(2, 2) = Eigen::Vector2d(-1.0, 0.7);  // elbow moving down
    forward_kinematics(m, data, data.x.head(2));
    const ImpactResult r = apply_impact(m, data, {0}, {}, m.contact.restitution);
    REQUIRE(r.solved);
    CAPTURE(e);
    CHECK(r.speed_before[0] < 0);
    CHECK(r.speed_after[0] == doctest::Approx(-e * r.speed_before[0]).epsilon(1e-12));
    // Delta KE = P (u- + u+) / 2; plastic: P |u-| / 2.
    CHECK(r.kinetic_before - r.kinetic_after ==
          doctest::Approx(-0.5 * r.impulse[0] * (r.speed_before[0] + r.speed_after[0])).epsilon(1e-12));
    if (e == 0.0)
      CHECK(r.kinetic_before - r.kinetic_after ==
            doctest::Approx(0.5 * r.impulse[0] * -r.speed_before[0]).epsilon(1e-12));
  }
}

TEST_CASE("impact with Coulomb friction: the contact point stops if mu allows, else slides on with |P_t| = mu P_n") {
  // The pressed tip (2 links, no motors, no gravity) hits the table moving down
  // and along +x. Reference by hand: the contact point's velocity changes by
  // G P, G = J_p M^-1 J_p^T (x and z rows), for the world impulse P = (P_t, P_n).
  // Plastic: stuck, P = -G^-1 u- if |P_t| <= mu P_n; else P_t = -mu P_n and
  // u+_z = 0. Rounding only: 1e-12.
  const PressedTip tip;
  for (const double mu : {2.0, 0.05}) {
    CAPTURE(mu);
    Model m = tip.model(0.0, 0.0, 0.1, 1e-3);
    REQUIRE(m.effects.motor == MotorModel::none);
    m.contact.friction.mu = mu;
    m.contact.restitution = 0.0;
    finalize(m);
    Data data(m);
    const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
    forward_kinematics(m, data, Eigen::Vector2d(tip.q1, tip.q2));
    Eigen::MatrixXd J3(3, 2);
    point_jacobian(m, data, 1, contact_point_local(data, 0, n), J3);
    Eigen::Matrix2d Jp;
    Jp << J3.row(0), J3.row(2);
    // The contact point moving at (0.3, -0.5) m/s.
    const Eigen::Vector2d qd = Jp.inverse() * Eigen::Vector2d(0.3, -0.5);
    place(m, data, Eigen::Vector2d(tip.q1, tip.q2), qd, 0.0);
    detect_contacts(m, data);
    mass_matrix_crba(m, data);
    const Eigen::Matrix2d W = data.mass_matrix.inverse();
    const Eigen::Matrix2d G = Jp * W * Jp.transpose();
    const Eigen::Vector2d u_before = Jp * qd;
    REQUIRE(u_before[1] < 0);  // approaching
    REQUIRE(u_before[0] > 0);  // sliding toward +x

    Eigen::Vector2d P = -G.inverse() * u_before;
    const bool sticks = std::abs(P[0]) <= mu * P[1];
    if (!sticks) {
      // P = P_n (-mu, 1) with (G P)_z = -u-_z.
      const Eigen::Vector2d d(-mu, 1.0);
      P = d * (-u_before[1] / G.row(1).dot(d));
    }
    CHECK(sticks == (mu == 2.0));  // the two cases are what they claim to be

    const ImpactResult r = apply_impact(m, data, {0}, {}, m.contact.restitution);
    REQUIRE(r.solved);
    const StateLayout s(m);
    const Eigen::Vector2d qd_after = data.x.segment(s.qd(), 2);
    CHECK(approx(qd_after, qd + W * Jp.transpose() * P, 1e-12));
    const Eigen::Vector2d u_after = Jp * qd_after;
    CHECK(std::abs(u_after[1]) < 1e-12);
    if (sticks) {
      CHECK(std::abs(u_after[0]) < 1e-12);
      CHECK(data.contact.sticking[0] == 1);
    } else {
      // Slides on the same way (faster, here: G's coupling of the normal
      // impulse outweighs friction's mu P_n).
      CHECK(u_after[0] > 0);
      CHECK(data.contact.sticking[0] == 0);
    }
    CHECK(r.kinetic_after < r.kinetic_before);
  }
}

TEST_CASE("land_touching_slots: an approaching elbow under the table lands, plastic impulse event") {
  // Plastic (e = 0): the elbow's normal speed after the impulse is zero, and the energy
  // the impulse takes is P |u-| / 2. Rounding only: 1e-12 relative.
  const Model m = falling_arm(0.0, EventTiming::step, 1e-3, 0.0);
  Data data = elbow_at_table(m, 1e-4, Eigen::Vector2d(-0.5, 0.3));
  REQUIRE(data.contact.detected[0].distance < 0);
  const double u_before = normal_speed(m, data, 0);
  REQUIRE(u_before < 0);
  land_touching_slots(m, data);
  REQUIRE(data.log.events.size() == 1);
  const ContactEvent& e = data.log.events[0];
  CHECK(e.kind == ContactEvent::Kind::landing);
  CHECK(e.slot == 0);
  CHECK(e.t == 0.123);
  CHECK(approx(e.speed, -u_before, 0, 1e-12));
  CHECK(e.impulse > 0);
  CHECK(approx(e.energy_lost, 0.5 * e.impulse * -u_before, 0, 1e-12));
  CHECK(data.contact.resting[0] == 1);
  CHECK(approx(data.contact.impact_loss, e.energy_lost, 0, 1e-12));
  CHECK(std::abs(normal_speed(m, data, 0)) < 1e-12 * std::abs(u_before));
}

TEST_CASE("land_touching_slots: without impacts the elbow lands with no impulse; qd unchanged") {
  Model m = falling_arm(0.0, EventTiming::step, 1e-3, 0.0);
  m.effects.impacts = false;
  finalize(m);
  Data data = elbow_at_table(m, 1e-4, Eigen::Vector2d(-0.5, 0.3));
  const double u_before = normal_speed(m, data, 0);
  const Eigen::VectorXd x_before = data.x;
  land_touching_slots(m, data);
  REQUIRE(data.log.events.size() == 1);
  CHECK(data.log.events[0].kind == ContactEvent::Kind::landing);
  CHECK(data.log.events[0].speed == -u_before);
  CHECK(data.log.events[0].impulse == 0);
  CHECK(data.contact.resting[0] == 1);
  CHECK(data.x == x_before);
  CHECK(data.contact.impact_loss == 0);
}

TEST_CASE("land_touching_slots: separating, above the table or already resting: no landing") {
  const Model step_mode = falling_arm(0.0, EventTiming::step, 1e-3, 0.0);
  SUBCASE("under the table but separating") {
    Data data = elbow_at_table(step_mode, 1e-4, Eigen::Vector2d(0.5, 0.0));
    land_touching_slots(step_mode, data);
    CHECK(data.log.events.empty());
    CHECK(data.contact.resting[0] == 0);
  }
  SUBCASE("approaching, 0.5 um above the table: lands only with located events (touch_distance 1 um)") {
    Data stepped = elbow_at_table(step_mode, -5e-7, Eigen::Vector2d(-0.5, 0.0));
    land_touching_slots(step_mode, stepped);
    CHECK(stepped.log.events.empty());
    const Model locate_mode = falling_arm(0.0, EventTiming::locate, 1e-3, 0.0);
    REQUIRE(locate_mode.contact.touch_distance == 1e-6);
    Data located = elbow_at_table(locate_mode, -5e-7, Eigen::Vector2d(-0.5, 0.0));
    land_touching_slots(locate_mode, located);
    CHECK(located.log.events.size() == 1);
    CHECK(located.contact.resting[0] == 1);
  }
  SUBCASE("already resting") {
    Data data = elbow_at_table(step_mode, 1e-4, Eigen::Vector2d(-0.5, 0.0));
    data.contact.resting[0] = 1;
    const Eigen::VectorXd x_before = data.x;
    land_touching_slots(step_mode, data);
    CHECK(data.log.events.empty());
    CHECK(data.x == x_before);
  }
}

TEST_CASE("apply_impact calls the C allocator zero times") {
  const Model m = falling_arm(0.0, EventTiming::step, 1e-3, 0.5);
  Data data = elbow_at_table(m, 1e-4, Eigen::Vector2d(-0.5, 0.3));
  const std::vector<int> landing{0}, resting;
  const Eigen::VectorXd x = data.x;
  apply_impact(m, data, landing, resting, m.contact.restitution);  // warm-up
  data.x = x;
  const long mallocs = malloc_count();
  const ImpactResult r = apply_impact(m, data, landing, resting, m.contact.restitution);
  const long calls = malloc_count() - mallocs;
  CHECK(r.solved);
  CHECK(calls == 0);
}

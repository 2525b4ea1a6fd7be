// engine/run/contact_events.cpp: landings and releases located inside a step (events:
// locate), locate_first_event on its own and through whole runs.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/detection.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/contact_events.hpp"
#include "engine/run/integrator.hpp"
#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("release: the elbow leaves when its force reaches zero (locate: within 1e-6 s)") {
  // tau1 = G1/2 + G1 t: the statics force (G1 - tau1)/(l1 cos q1) is zero at t* = 0.5 s.
  const ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), arm.G1());
  m.contact.events = EventTiming::locate;
  m.contact.locate_tolerance = 1e-10;
  finalize(m);
  const RunResult located = simulate(m, {});
  REQUIRE(located.completed);
  const ContactEvent* e = first_event(located, ContactEvent::Kind::release);
  REQUIRE(e != nullptr);
  MESSAGE("release located at ", e->t, " s (analytic 0.5 s)");
  CHECK(std::abs(e->t - 0.5) < 1e-6);
  m.contact.events = EventTiming::step;
  finalize(m);
  const RunResult stepped = simulate(m, {});
  const ContactEvent* s = first_event(stepped, ContactEvent::Kind::release);
  REQUIRE(s != nullptr);
  CHECK(s->t >= 0.5 - 1e-12);
  CHECK(s->t <= 0.5 + 1e-3 + 1e-12);  // at the first step boundary after it
}

TEST_CASE("landing: located landing time matches a fine reference within 1e-6 s; plastic impact") {
  const RunResult coarse = simulate(falling_arm(0.15, EventTiming::locate, 1e-3, 0.0), {});
  const RunResult fine = simulate(falling_arm(0.15, EventTiming::locate, 1e-4, 0.0), {});
  const RunResult stepped = simulate(falling_arm(0.15, EventTiming::step, 1e-3, 0.0), {});
  REQUIRE(coarse.completed);
  const ContactEvent* a = first_event(coarse, ContactEvent::Kind::landing);
  const ContactEvent* b = first_event(fine, ContactEvent::Kind::landing);
  const ContactEvent* c = first_event(stepped, ContactEvent::Kind::landing);
  REQUIRE(a != nullptr);
  REQUIRE(b != nullptr);
  REQUIRE(c != nullptr);
  MESSAGE("landing at ", a->t, " s (step 1e-3, locate), ", b->t, " s (step 1e-4), ", c->t,
          " s (step mode); speed ", a->speed, " m/s, impulse ", a->impulse, " N s");
  CHECK(std::abs(a->t - b->t) < 1e-6);
  CHECK(c->t >= a->t);
  CHECK(c->t < a->t + 1e-3 + 1e-9);
  CHECK(a->speed > 0.1);
  CHECK(a->impulse > 0);
  // Every impact's loss is in the account: the elbow's, and link 1's tip landing
  // when the unactuated forearm swings down onto the table after it.
  double lost = 0;
  int landings = 0;
  for (const ContactEvent& e : coarse.events)
    if (e.kind == ContactEvent::Kind::landing) lost += e.energy_lost, ++landings;
  CHECK(landings >= 2);
  CHECK(coarse.energy_final.impact_loss == doctest::Approx(lost).epsilon(1e-9));
  // The energy account closes with the impact loss in it.
  CHECK(std::abs(coarse.balance_residual) < 1e-6 * coarse.energy_final.impact_loss);
}


TEST_CASE("locate_first_event: a step that crosses the table is cut at the landing, |d| <= |v| tol") {
  // The unactuated elbow arm, its elbow 0.1 mm above the table falling at ~0.4 m/s:
  // one 1 ms step takes it 0.3 mm into the table. Located, the step ends just past the
  // touch (the root finder keeps the far side), so the elbow is at most
  // |normal speed| x locate_tolerance (1e-12 s) deep, plus Bullet's rounding (1e-15 m).
  const ElbowArm arm;
  const Model m = falling_arm(0.0, EventTiming::locate, 1e-3, 0.0);
  Data data(m);
  const double above = 1e-4 / (arm.l1 * std::cos(arm.q1));  // shoulder angle for 0.1 mm
  const double t0 = 0.2;
  place(m, data, Eigen::Vector2d(arm.q1 + above, arm.q2), Eigen::Vector2d(-1.0, 0.0), t0);
  prepare_integrator(m, data);
  detect_contacts(m, data);
  // 1e-4 m to first order in the angle; the second-order term l1 sin(q1) da^2 / 2 is 4e-9 m.
  REQUIRE(approx(data.contact.detected[0].distance, 1e-4, 1e-8));
  data.x_start = data.x;
  integrate_step(m, data, 1e-3);
  detect_contacts(m, data);
  REQUIRE(data.contact.detected[0].distance < -1e-4);  // the whole step went through the table

  locate_first_event(m, data, t0);
  const double d = data.contact.detected[0].distance, v = normal_speed(m, data, 0);
  MESSAGE("landing located at t0 + ", data.t - t0, " s: distance ", d, " m at ", v, " m/s");
  CHECK(data.t > t0);
  CHECK(data.t < t0 + 1e-3);
  CHECK(d <= 0);
  CHECK(-d <= std::abs(v) * m.contact.locate_tolerance + 1e-15);
  CHECK(v < 0);                          // still approaching: the impact stage handles it
  CHECK(data.log.events.empty());        // a landing is recorded by the impact stage
  CHECK(data.contact.resting[0] == 0);
  CHECK(data.step_count == 1);           // the redone step replaced the first
}

TEST_CASE("locate_first_event with events: step leaves the step whole and only detects") {
  const ElbowArm arm;
  const Model m = falling_arm(0.0, EventTiming::step, 1e-3, 0.0);
  Data data(m);
  const double above = 1e-4 / (arm.l1 * std::cos(arm.q1));
  place(m, data, Eigen::Vector2d(arm.q1 + above, arm.q2), Eigen::Vector2d(-1.0, 0.0), 0.2);
  prepare_integrator(m, data);
  data.x_start = data.x;
  integrate_step(m, data, 1e-3);
  const Eigen::VectorXd x_end = data.x;
  const double t_end = data.t;
  locate_first_event(m, data, 0.2);
  CHECK(data.t == t_end);
  CHECK(data.x == x_end);
  CHECK(data.contact.detected[0].distance < -1e-4);  // detection at the step's end
  CHECK(data.log.events.empty());
}

TEST_CASE("locate_first_event: a resting elbow whose force turns negative is released at its zero") {
  // tau1 = G1/2 + G1 t: the statics force (G1 - tau1)/(l1 cos q1) crosses zero at
  // t* = 0.5 s, inside the step [0.4995, 0.5005]. The arm is in equilibrium (C = 0,
  // Cd = 0, link 1 held by G2), so the force is exactly linear in t and the located
  // time is t* within locate_tolerance (1e-10 s) plus rounding: 2e-10 s.
  const ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), arm.G1());
  m.contact.events = EventTiming::locate;
  m.contact.locate_tolerance = 1e-10;
  finalize(m);
  Data data(m);
  const double t0 = 0.4995;
  place(m, data, Eigen::Vector2d(arm.q1, arm.q2), Eigen::Vector2d::Zero(), t0);
  prepare_integrator(m, data);
  data.contact.resting[0] = 1;
  data.contact.active = {0};
  detect_contacts(m, data);
  freeze_frames(data);  // the table normal and point of the row
  data.x_start = data.x;
  integrate_step(m, data, 1e-3);

  locate_first_event(m, data, t0);
  MESSAGE("release located at ", data.t, " s (analytic 0.5 s)");
  CHECK(std::abs(data.t - 0.5) < 2e-10);
  REQUIRE(data.log.events.size() == 1);
  CHECK(data.log.events[0].kind == ContactEvent::Kind::release);
  CHECK(data.log.events[0].slot == 0);
  CHECK(data.log.events[0].t == data.t);
  CHECK(data.contact.resting[0] == 0);
  CHECK(data.step_count == 1);
}

TEST_CASE("an elbow sliding off the table's edge releases at the edge") {
  // The pressed tip (friction mu 0.5, f_n 10 N) pushed along +x with 1.5 mu f_n
  // slides toward the box's edge 2 cm ahead. A ball of 2 mm radius reaches it
  // at ~0.3 m/s: v^2 / r ~ 50 m/s^2 outruns the ~10 m/s^2 the push presses it
  // down with, so it cannot follow the edge round: it leaves as its centre
  // passes over the edge, x_c = x_edge to (speed x locate tolerance).
  PressedTip tip;
  tip.r = 0.002;
  Model m = tip.model(1.5, 0.0, 0.3, 1e-3);
  const double x_edge = tip.tip().x() + 0.02;
  TableBox& box = m.table[0];
  box.center.x() = x_edge - 0.5 * box.size.x();
  m.contact.locate_tolerance = 1e-12;
  finalize(m);
  const RunResult r = simulate(m, {});
  REQUIRE(r.completed);
  const ContactEvent* release = first_event(r, ContactEvent::Kind::release);
  REQUIRE(release != nullptr);
  CHECK(r.valid);

  // The state at the release: the same run stopped there.
  m.options.duration = release->t;
  finalize(m);
  const RunResult until = simulate(m, {});
  Data data(m);
  forward_kinematics(m, data, Eigen::Vector2d(last(until, "q0"), last(until, "q1")));
  const Eigen::Vector3d centre = point_position(data, 1, m.elbows[0].point);
  const double speed = std::hypot(last(until, "qd0"), last(until, "qd1")) * (tip.l1 + tip.l2);
  MESSAGE("released at t = ", release->t, " s with the centre ", centre.x() - x_edge,
          " m past the edge (joint-speed bound ", speed, " m/s)");
  CHECK(std::abs(centre.x() - x_edge) <= speed * 1e-12 + 1e-12);
  CHECK(std::abs(centre.z() - (box.center.z() + 0.5 * box.size.z() + tip.r)) < 1e-9);
}

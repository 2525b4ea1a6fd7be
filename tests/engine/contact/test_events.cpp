// engine/contact/events.cpp: landings and releases located inside a step (events:
// locate), locate_first_event on its own and through whole runs.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/detection.hpp"
#include "engine/contact/events.hpp"
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
  const ContactEvent* s = first_event(simulate(m, {}), ContactEvent::Kind::release);
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
  CHECK(coarse.energy_final.impact_loss == doctest::Approx(a->energy_lost).epsilon(1e-9));
  // The energy account closes with the impact loss in it.
  CHECK(std::abs(coarse.balance_residual) < 1e-6 * coarse.energy_final.impact_loss);
}

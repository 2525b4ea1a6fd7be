// engine/run/step.cpp: the step function on its own: driven by hand it is simulate(),
// it allocates nothing even when elbows land, bounce, release and slide, and it refuses
// a Data made for another model.
#include <doctest/doctest.h>

#include <cmath>

#include <cstring>
#include <stdexcept>

#include "engine/contact/collision.hpp"
#include "engine/run/recorder.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/allocations.hpp"
#include "engine/control/plan.hpp"
#include "engine/state_layout.hpp"
#include "engine/step_grid.hpp"
#include "support/contact_scenes.hpp"
#include "support/experiment_scenes.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The elbow arm dropped 0.1 rad above its resting pose onto the table with
// restitution 0.5 (it lands, bounces off, lands again) and sliding friction;
// the shoulder torque then lifts it off again at ~0.8 s.
//
//          o----- hand
//        /      (falls, bounces, rests, slides, lifts off)
//   o---o
//   ======  table
Model bouncing_arm(EventTiming events, Stabilization stabilization) {
  const ElbowArm arm;
  Model m = arm.model(0.0, 0.0);
  m.inputs.joints[0].kind = InputProfile::Kind::table;
  m.inputs.joints[0].times = {0.0, 0.6, 1.0};
  m.inputs.joints[0].values = {0.5 * arm.G1(), 0.5 * arm.G1(), 1.4 * arm.G1()};
  m.initial.q[0] += 0.1;
  m.effects.friction = true;
  m.contact.friction.mu = 0.3;
  m.contact.restitution = 0.5;
  m.contact.events = events;
  m.effects.stabilization = stabilization;
  m.options = {1.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  // With events: step a landing is found a step late, up to speed x step deep: the
  // forearm lands at ~4 m/s here (4 mm at 1 ms), which the default 1 mm would call
  // invalid. The guard is about allocation, not about this scene's accuracy.
  if (events == EventTiming::step) m.contact.penetration_tolerance = 0.01;
  finalize(m);
  return m;
}

struct Counts {
  int landings = 0, releases = 0, impacts = 0, steps = 0;
};

void count(const Data& data, Counts& c) {
  ++c.steps;
  for (const ContactEvent& e : data.log.events) {
    if (e.kind == ContactEvent::Kind::release) ++c.releases;
    if (e.kind == ContactEvent::Kind::landing) ++c.landings;
    if (e.impulse > 0) ++c.impacts;
  }
}

}  // namespace

TEST_CASE("a contact step allocates nothing: 1,000 steps with landings, releases, impacts, friction") {
  double sliding_loss = 0;  // [J] over the four variants
  for (EventTiming events : {EventTiming::step, EventTiming::locate}) {
    for (Stabilization s : {Stabilization::baumgarte, Stabilization::projection}) {
      // Captured before counting: doctest's context list may allocate.
      CAPTURE(std::string(to_string(events)));
      CAPTURE(std::string(to_string(s)));
      const Model m = bouncing_arm(events, s);
      Data data(m);
      reset(m, data);  // builds the collision world: the one allocation of a run
      Counts counts;
      const long news = allocation_count(), bullet = CollisionWorld::bullet_allocations();
      Eigen::internal::set_is_malloc_allowed(false);
      while (!finished(m, data) && !data.failure) {
        step(m, data);
        count(data, counts);
      }
      Eigen::internal::set_is_malloc_allowed(true);
      CHECK(allocation_count() == news);
      CHECK(CollisionWorld::bullet_allocations() == bullet);
      CHECK_FALSE(data.failure);
      CHECK(counts.steps >= 1000);
      // The scene did what the guard is meant to cover.
      CHECK(counts.landings >= 2);
      CHECK(counts.releases >= 2);
      CHECK(counts.impacts >= 1);
      // Friction never gives energy back; with projection and events at step
      // ends the settled elbow sticks throughout (no sliding loss there).
      const StateLayout layout(m);
      CHECK(data.x[layout.energy + 3] > -1e-12);
      sliding_loss += data.x[layout.energy + 3];
    }
  }
  CHECK(sliding_loss > 1e-6);  // sliding friction was stepped through
}

TEST_CASE("step() driven by hand reproduces simulate() bit for bit on a contact scene") {
  const Model m = bouncing_arm(EventTiming::locate, Stabilization::baumgarte);
  const RunResult run = simulate(m, RunOptions{1, {}});
  REQUIRE(run.completed);

  // simulate() ends fixed steps on the rows (every step's length here) and
  // records there: a step grid shifted by an event realigns on the next row.
  Recording by_hand(trajectory_layout(m, false));
  Data data(m);
  data.record_interval = m.options.step;
  reset(m, data);
  record_sample(m, data, by_hand);
  std::vector<ContactEvent> events(data.log.events);
  double last_row = 0;
  while (!finished(m, data)) {
    step(m, data);
    REQUIRE_FALSE(data.failure);
    events.insert(events.end(), data.log.events.begin(), data.log.events.end());
    const double k = std::round(data.t / m.options.step);
    const bool row = k > last_row && step_grid::on_row(data.t, k, m.options.step, m.options.step);
    if (!row && !finished(m, data)) continue;
    if (row) last_row = k;
    evaluate_outputs(m, data);
    record_sample(m, data, by_hand);
  }
  REQUIRE(by_hand.values.size() == run.trajectory.values.size());
  CHECK(std::memcmp(by_hand.values.data(), run.trajectory.values.data(),
                    by_hand.values.size() * sizeof(double)) == 0);
  REQUIRE(events.size() == run.events.size());
  for (std::size_t k = 0; k < events.size(); ++k) {
    CHECK(events[k].t == run.events[k].t);
    CHECK(events[k].impulse == run.events[k].impulse);
  }
}

TEST_CASE("a Data made for one model is refused by another") {
  const Model pendulum_model = pendulum(IntegratorKind::rk4, 1e-3, 0.1);
  const Model arm = driven_arm(IntegratorKind::rk4, 1e-3, 0.1, 1e-3);
  Data data(pendulum_model);
  CHECK_NOTHROW(reset(pendulum_model, data));
  CHECK_NOTHROW(step(pendulum_model, data));
  // Same dof, another state layout (motor currents): the sizes differ.
  CHECK_THROWS_AS(step(arm, data), std::invalid_argument);
  CHECK_THROWS_AS(reset(arm, data), std::invalid_argument);
  // Same sizes, but finalized anew (another model): the id differs.
  Model copy = pendulum_model;
  finalize(copy);
  try {
    step(copy, data);
    FAIL("no error");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("model id") != std::string::npos);
  }
}

TEST_CASE("a step's events are in data.log, at the step's end") {
  const Model m = bouncing_arm(EventTiming::locate, Stabilization::baumgarte);
  Data data(m);
  reset(m, data);
  while (!finished(m, data) && data.log.events.empty()) step(m, data);
  REQUIRE(data.log.events.size() >= 1);
  const ContactEvent& e = data.log.events.front();
  CHECK(e.kind == ContactEvent::Kind::landing);
  CHECK(e.t == data.t);  // located: the step was shortened to end on the landing
  CHECK(e.impulse > 0);
  const double landed = e.t;
  // The bounce (restitution 0.5) leaves the table at the impact: released in
  // the same log, at the same instant.
  REQUIRE(data.log.events.size() == 2);
  CHECK(data.log.events[1].kind == ContactEvent::Kind::release);
  CHECK(data.log.events[1].t == landed);
  // The log is emptied: the next step holds only its own events (none here).
  step(m, data);
  CHECK(data.log.events.empty());
}

TEST_CASE("a contact step calls the C allocator zero times: Eigen's allocations counted too") {
  // The guard above (Eigen's set_is_malloc_allowed) reports through eigen_assert, which
  // Release builds (-DNDEBUG) compile out, and Eigen allocates with malloc, unseen by
  // operator new: this counts malloc itself (support/malloc_count.cpp).
  for (EventTiming events : {EventTiming::step, EventTiming::locate}) {
    for (Stabilization s : {Stabilization::baumgarte, Stabilization::projection}) {
      const Model m = bouncing_arm(events, s);
      Data data(m);
      reset(m, data);
      Counts counts;
      const long mallocs = malloc_count();
      while (!finished(m, data) && !data.failure) {
        step(m, data);
        count(data, counts);
      }
      const long during = malloc_count() - mallocs;
      CAPTURE(std::string(to_string(events)));
      CAPTURE(std::string(to_string(s)));
      CHECK(during == 0);
      CHECK(counts.landings >= 2);
      CHECK(counts.releases >= 2);
    }
  }
}

TEST_CASE("the experiment's contact steps allocate nothing: 1,000 steps, controller and plan on") {
  // The paper's experiment (a 4-link arm resting its elbow, tracking a hand path
  // with PD + feed-forward): every derivative evaluation runs the control law, the
  // motors and the constrained solve. Counted: operator new, the C allocator
  // (Eigen), Bullet's allocator, and Eigen's own guard (debug builds).
  const ExperimentScene scene = WritingArm{}.scene();
  const Model& m = scene.model;
  Data data(m);
  data.controller = make_controller(m, scene.experiment);
  reset(m, data);
  long steps = 0, resting = 0;
  const long news = allocation_count(), mallocs = malloc_count();
  const long bullet = CollisionWorld::bullet_allocations();
  Eigen::internal::set_is_malloc_allowed(false);
  for (; steps < 1000 && !data.failure; ++steps) {
    step(m, data);
    resting += !data.contact.active.empty();
  }
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(allocation_count() - news == 0);
  CHECK(malloc_count() - mallocs == 0);
  CHECK(CollisionWorld::bullet_allocations() == bullet);
  CHECK_FALSE(data.failure);
  CHECK(steps == 1000);
  CHECK(resting >= 900);  // the elbow rested: the constrained solve ran
}

// engine/run/warnings.cpp: each warning fires on a run or recording made to
// trigger it, names the quantity, the value and the threshold, and stays
// quiet on one that does not; a warned run is valid all the same.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "engine/contact/primitives.hpp"
#include "engine/run/fixed_step_stability.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/warnings.hpp"
#include "support/experiment_scenes.hpp"
#include "support/models.hpp"
#include "support/recordings.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Two joints with motors, 11 rows 0.1 s apart (1 s): voltages and speeds set per row.
struct TwoMotors {
  Model model = driven_arm(IntegratorKind::rk4, 1e-3, 1.0, 5e-4);
  Recording rec;
  TwoMotors() {
    TrajectoryLayout::Groups g;
    g.dof = 2;
    g.motors = true;
    rec = zero_recording(g, 11);
    for (std::size_t r = 0; r < 11; ++r) set(rec, r, rec.layout.time(), 0.1 * double(r));
  }
};

}  // namespace

TEST_CASE(
    "saturation_shares: the share of recorded time at the voltage limit, a row holding until the "
    "next") {
  TwoMotors arm;
  const double limit = arm.model.voltage_limit[0];
  // Motor 0 at +limit in rows 0-2 and -limit in row 9 (4 of 10 intervals); the
  // last row (10) stands for no time. Motor 1 just inside the limit.
  for (std::size_t r : {0u, 1u, 2u, 9u, 10u})
    set(arm.rec, r, arm.rec.layout.voltage(0), r == 9 ? -limit : limit);
  for (std::size_t r = 0; r < 11; ++r) set(arm.rec, r, arm.rec.layout.voltage(1), 0.999 * limit);
  const std::vector<double> shares = saturation_shares(arm.model, arm.rec);
  REQUIRE(shares.size() == 2);
  CHECK(shares[0] == doctest::Approx(0.4).epsilon(1e-12));
  CHECK(shares[1] == 0.0);
  // Above warnings.saturation_share (5 %) for motor 0 only, with its numbers.
  const std::vector<std::string> w = saturation_warnings(arm.model, shares);
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("motor 0 is at its voltage limit (24 V) for 40 % of the run") == 0);
  CHECK(contains(w[0], "saturation_share 5 %"));
  arm.model.warn.saturation_share = 0.5;
  CHECK(saturation_warnings(arm.model, shares).empty());
}

TEST_CASE("saturation_shares: with a current limit, the voltage window's edge counts too") {
  TwoMotors arm;
  arm.model.motors[1].current_limit = 2.0;
  finalize(arm.model);
  REQUIRE(arm.model.current_limit[1] == 2.0);
  // v - Km qd = R i_max: the current limit holds motor 1 (rows 0-4, half the run).
  const double km = arm.model.km[1], window = arm.model.resistance[1] * 2.0;
  for (std::size_t r = 0; r < 5; ++r) {
    set(arm.rec, r, arm.rec.layout.qd(1), 0.5);
    set(arm.rec, r, arm.rec.layout.voltage(1), km * 0.5 + window);
  }
  const std::vector<double> shares = saturation_shares(arm.model, arm.rec);
  CHECK(shares[0] == 0.0);
  CHECK(shares[1] == doctest::Approx(0.5).epsilon(1e-12));
  CHECK(contains(saturation_warnings(arm.model, shares).at(0), "or current limit (2 A)"));
}

TEST_CASE("hand_error_warnings: the largest distance, when and the threshold; none within it") {
  TrajectoryLayout::Groups g;
  g.dof = 2;
  g.desired_hand = true;
  Recording rec = zero_recording(g, 5);
  Model model = planar_arm({{0.4, 1.0, 0.2, 0.01}, {0.3, 1.0, 0.15, 0.01}});
  for (std::size_t r = 0; r < 5; ++r) {
    set(rec, r, rec.layout.time(), 0.5 * double(r));
    set(rec, r, rec.layout.hand_error(), r == 3 ? 2.5e-3 : 1e-4);
  }
  const std::vector<std::string> w = hand_error_warnings(model, rec);
  REQUIRE(w.size() == 1);
  CHECK(w[0] ==
        "the hand was 2.5 mm from its desired point at t = 1.5 s, above warnings: "
        "hand_error (1 mm): the arm did not do the task it was given");
  model.warn.hand_error = 3e-3;
  CHECK(hand_error_warnings(model, rec).empty());
  TrajectoryLayout::Groups no_task;  // no task: no hand error
  no_task.dof = 2;
  CHECK(hand_error_warnings(model, zero_recording(no_task, 5)).empty());
}

TEST_CASE("lift_off_warnings: a planned elbow's release events, the first time and the count") {
  WritingArm arm;
  const ExperimentScene scene = arm.scene();
  const ContactGeometry geometry = contact_geometry(scene.model);
  REQUIRE(scene.model.elbows.size() == 1);
  std::vector<ContactEvent> events(3);
  events[0] = {0.64, 0, ContactEvent::Kind::release};
  events[1] = {0.70, 0, ContactEvent::Kind::landing};
  events[2] = {1.25, 0, ContactEvent::Kind::release};
  REQUIRE(geometry.primitives[std::size_t(geometry.slots[0].primitive)].elbow == 0);
  const std::vector<std::string> w = lift_off_warnings(scene.model, geometry, events, {0});
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("elbow 'elbow', which the task keeps on the table, lifted off at t = 0.64 s "
                  "(2 times in all)") == 0);
  CHECK(lift_off_warnings(scene.model, geometry, events, {}).empty());  // not planned to rest
  events.erase(events.begin() + 2);
  events.erase(events.begin());
  CHECK(lift_off_warnings(scene.model, geometry, events, {0}).empty());  // a landing only
}

TEST_CASE(
    "motor ratings: a motor above its rated continuous current warns with the ratio; a valid run "
    "all the same") {
  WritingArm arm;
  arm.elbow_on = false;  // the shoulder holds the arm out: the largest current
  ExperimentScene scene = arm.scene();
  const RunResult unrated = simulate(scene.model, scene.experiment, RunOptions{10, {}});
  REQUIRE(unrated.valid);
  const double shoulder = unrated.metrics.find("current_rms")->values[0];
  for (const std::string& w : unrated.warnings)
    CHECK(w.find("rated continuous") == std::string::npos);
  scene.model.motors[0].rated_current = 0.5 * shoulder;
  scene.model.motors[1].rated_current = 1e3;  // far above: no warning
  finalize(scene.model);
  const RunResult r = simulate(scene.model, scene.experiment, RunOptions{10, {}});
  CHECK(r.valid);
  int found = 0;
  for (const std::string& w : r.warnings)
    if (w.find("rated continuous") != std::string::npos) {
      ++found;
      CHECK(w.find("motor 0 carries") == 0);
      CHECK(w.find("2 times its rated continuous current") != std::string::npos);
    }
  CHECK(found == 1);
}

TEST_CASE(
    "stiffness warning: a fixed step far above L/R says so and names the fix; adaptive runs do "
    "not") {
  auto arm = [](IntegratorKind kind, double inductance) {
    Model m = driven_arm(kind, 1e-3, 0.05, inductance);
    for (Motor& motor : m.motors) motor.resistance = 1.0;
    finalize(m);
    return m;
  };
  auto stiffness = [](const Model& m) {
    for (const std::string& w : stiffness_warnings(m))
      if (w.find("electrical time constant") != std::string::npos) return w;
    return std::string();
  };
  const std::string w = stiffness(arm(IntegratorKind::rk4, 1e-6));  // L/R = 1 us against 1 ms
  CHECK(w.find("motor 0's electrical time constant L/R = 1e-06 s") == 0);
  CHECK(w.find("the rk4 integrator is stable there on the motor-arm system linearised at "
               "initial.q") != std::string::npos);
  CHECK(w.find("only first-order accurate") != std::string::npos);
  CHECK(w.find("ros34pw2") != std::string::npos);
  CHECK(stiffness(arm(IntegratorKind::rk4, 5e-4)).empty());       // 0.5 ms: resolved enough
  CHECK(stiffness(arm(IntegratorKind::ros34pw2, 1e-6)).empty());  // adaptive: its own error control
  // And the run carries it.
  const RunResult r = simulate(arm(IntegratorKind::rk4, 1e-6), {});
  bool carried = false;
  for (const std::string& x : r.warnings) carried = carried || x == w;
  CHECK(carried);
}

TEST_CASE(
    "stiffness warning: beyond the fixed step's stability limit it says unstable, never stable") {
  Model m = driven_arm(IntegratorKind::rk4, 1e-3, 5.0, 1e-6);
  for (Motor& motor : m.motors) motor.resistance = 1.0;
  finalize(m);
  const double limit =
      stable_step_limit(IntegratorKind::rk4, linearise_arm(m, nullptr, m.initial.q), 1e-3);
  m.options.step = 1.2 * limit;
  finalize(m);
  const std::vector<std::string> said = stiffness_warnings(m);
  REQUIRE(said.size() == 1);
  MESSAGE(said[0]);
  CHECK(said[0].starts_with("the rk4 integrator is unstable at the step"));
  CHECK(contains(said[0], "stable up to a step of about"));
  CHECK(contains(said[0], "L/R = 1e-06 s is under a tenth of the step"));
  CHECK(contains(said[0], "use simulation.integrator: ros34pw2"));
  CHECK_FALSE(contains(said[0], "stable there"));
  // And it is: the run diverges, its failure led by the same clause.
  const RunResult r = simulate(m, {});
  CHECK_FALSE(r.completed);
  CHECK(r.failure.starts_with("the rk4 integrator is unstable at the step"));
  CHECK(contains(r.failure, "likely as a result, simulation diverged"));
  // Within the limit it is quiet about stability (the electrics warning aside).
  m.options.step = 0.5 * limit;
  finalize(m);
  for (const std::string& w : stiffness_warnings(m)) CHECK_FALSE(contains(w, "unstable"));
}

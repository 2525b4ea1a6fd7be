// engine/control/controller.cpp: the control law command() on its own (open loop, PD,
// PD + feed-forward, force, no motors), and tracking through whole runs.
#include <doctest/doctest.h>

#include <memory>

#include "engine/control/controller.hpp"
#include "engine/control/plan.hpp"
#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("PD + feed-forward tracks the slow line; PD alone sags under gravity, more with the elbow off") {
  auto run = [](bool elbow_on, ControllerSpec::Kind kind) {
    WritingArm arm;
    arm.elbow_on = elbow_on;
    arm.controller = kind;
    const auto [model, experiment] = arm.scene();
    const RunResult r = simulate(model, experiment, RunOptions{10, {}});
    REQUIRE(r.completed);
    return r.metrics;
  };
  for (bool elbow_on : {true, false}) {
    const Metrics m = run(elbow_on, ControllerSpec::Kind::pd_feedforward);
    MESSAGE("PD+FF elbow ", std::string(elbow_on ? "on" : "off"), ": max hand error ", m["hand_error_max"], " m");
    // The feed-forward is the exact inverse model; what is left is the plan's
    // 1 ms sampling and its finite-difference rates (measured ~1e-8 m).
    CHECK(m["hand_error_max"] < 1e-6);
  }
  const Metrics on = run(true, ControllerSpec::Kind::pd), off = run(false, ControllerSpec::Kind::pd);
  MESSAGE("PD alone, final hand error: elbow on ", on["hand_error_final"], " m, off ", off["hand_error_final"], " m");
  // Proportional control needs an error to make torque: the arm sags until
  // Kp e balances gravity. With the elbow resting the table carries most of it.
  CHECK(on["hand_error_final"] > 1e-3);
  CHECK(off["hand_error_final"] > 5 * on["hand_error_final"]);
}

// engine/control/plan.cpp: the plan (IK samples on the step, central differences, the
// feed-forward voltages) and the controller built on it; errors for tasks that cannot be
// followed; force control through the plan's commanded elbow force.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/control/plan.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("IK: an unreachable target is a clear error with the time and the distance missed") {
  WritingArm arm;
  auto [m, x] = arm.scene();
  x.task.points[1] = x.task.points[0] + Eigen::Vector3d(1.0, 0, 0);  // 1 m further: out of reach
  try {
    make_plan(m, x);
    FAIL("no error");
  } catch (const PlanError& e) {
    const std::string msg = e.what();
    MESSAGE(msg);
    CHECK(msg.find("out of reach") != std::string::npos);
    CHECK(msg.find("at t = ") != std::string::npos);
    CHECK(msg.find("missed by ") != std::string::npos);
  }
}

TEST_CASE("force control holds the commanded elbow force in a quasi-static motion") {
  WritingArm arm;
  arm.controller = ControllerSpec::Kind::force;
  auto [m, x] = arm.scene();
  for (double desired : {2.0, 5.0, 10.0}) {
    x.controller.desired_force = desired;
    const RunResult r = simulate(m, x, RunOptions{10, {}});
    REQUIRE(r.completed);
    CAPTURE(desired);
    // The band: 1 % of the command. The estimate comes from the algebraic
    // relation of M* with the exact model, so only tracking errors remain.
    CHECK(r.metrics["elbow_force_min"] > 0.99 * desired);
    CHECK(r.metrics["elbow_force_max"] < 1.01 * desired);
    CHECK(r.metrics["time_in_contact"] == doctest::Approx(m.options.duration));
  }
}

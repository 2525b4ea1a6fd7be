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

namespace {

// Two joints with quasi-static servos; open-loop inputs: a sine on joint 0, a table on 1.
Model two_servos(MotorModel motor) {
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.2, 0.5, 0.1, 0.005}});
  m.effects.motor = motor;
  m.motors = {small_servo(), small_servo()};
  InputProfile sine, table;
  sine.kind = InputProfile::Kind::sine;
  sine.amplitude = 3.0, sine.frequency = 2.0, sine.offset = 1.0, sine.phase = 0.3;
  table.kind = InputProfile::Kind::table;
  table.times = {0.0, 1.0};
  table.values = {-2.0, 4.0};
  m.inputs.joints = {sine, table};
  finalize(m);
  return m;
}

// A hand-made plan: three samples 0.1 s apart.
std::shared_ptr<const Controller> controller(ControllerSpec::Kind kind) {
  auto plan = std::make_shared<Plan>();
  plan->dt = 0.1;
  plan->q = {Eigen::Vector2d(0.0, 0.5), Eigen::Vector2d(0.25, 0.75), Eigen::Vector2d(1.0, 0.25)};
  plan->qd = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(2.0, -1.0), Eigen::Vector2d(4.0, 1.0)};
  plan->v_ff = {Eigen::Vector2d(1.0, 2.0), Eigen::Vector2d(3.0, -4.0), Eigen::Vector2d(5.0, 6.0)};
  plan->hand.assign(3, Eigen::Vector3d::Zero());
  auto c = std::make_shared<Controller>();
  c->spec.kind = kind;
  c->spec.kp = Eigen::Vector2d(10.0, 20.0);
  c->spec.kd = Eigen::Vector2d(0.5, 2.0);
  c->plan = plan;
  return c;
}

}  // namespace

TEST_CASE("command open loop: the input profile of each joint at t, as the voltage") {
  const Model m = two_servos(MotorModel::quasi_static);
  Data data(m);
  const Eigen::Vector2d q(0.1, 0.2), qd(-1.0, 1.0);
  for (const double t : {0.0, 0.13, 0.5, 2.0}) {
    CAPTURE(t);
    command(m, data, t, q, qd);
    CHECK(data.voltage[0] == m.inputs.joints[0].at(t));
    CHECK(data.voltage[1] == m.inputs.joints[1].at(t));
  }
  // An open_loop controller, even with a plan, plays the profiles too.
  data.controller = controller(ControllerSpec::Kind::open_loop);
  command(m, data, 0.5, q, qd);
  CHECK(data.voltage == Eigen::Vector2d(m.inputs.joints[0].at(0.5), 1.0));
  // No profiles: zero.
  Model silent = m;
  silent.inputs.joints.clear();
  finalize(silent);
  Data quiet(silent);
  quiet.voltage.setConstant(9.0);
  command(silent, quiet, 0.5, q, qd);
  CHECK(quiet.voltage.isZero());
}

TEST_CASE("command PD: v = Kp (q_d - q) + Kd (qd_d - qd) with the plan at t") {
  const Model m = two_servos(MotorModel::full);
  Data data(m);
  data.controller = controller(ControllerSpec::Kind::pd);
  const Eigen::Vector2d q(0.125, 1.0), qd(1.5, 0.5);
  // On a sample (t = 0.1: u = 1 exactly), all products exact in binary: ==.
  command(m, data, 0.1, q, qd);
  CHECK(data.q_desired == Eigen::Vector2d(0.25, 0.75));
  CHECK(data.qd_desired == Eigen::Vector2d(2.0, -1.0));
  CHECK(data.voltage == Eigen::Vector2d(10.0 * (0.25 - 0.125) + 0.5 * (2.0 - 1.5),
                                        20.0 * (0.75 - 1.0) + 2.0 * (-1.0 - 0.5)));
  CHECK(data.v_feedforward.isZero());  // PD alone has no feed-forward
  // Between samples the plan is interpolated: rounding of t / dt, 1e-12 V.
  command(m, data, 0.15, q, qd);
  const Eigen::Vector2d q_d(0.625, 0.5), qd_d(3.0, 0.0);
  CHECK(approx(data.voltage, Eigen::Vector2d(Eigen::Vector2d(10.0, 20.0).cwiseProduct(q_d - q) +
                                             Eigen::Vector2d(0.5, 2.0).cwiseProduct(qd_d - qd)),
               1e-12));
}

TEST_CASE("command PD + feed-forward and force control add the plan's v_ff at t") {
  const Model m = two_servos(MotorModel::full);
  const Eigen::Vector2d q(0.125, 1.0), qd(1.5, 0.5);
  const Eigen::Vector2d pd(10.0 * (0.25 - 0.125) + 0.5 * (2.0 - 1.5),
                           20.0 * (0.75 - 1.0) + 2.0 * (-1.0 - 0.5));
  for (ControllerSpec::Kind kind : {ControllerSpec::Kind::pd_feedforward, ControllerSpec::Kind::force}) {
    CAPTURE(std::string(to_string(kind)));
    Data data(m);
    data.controller = controller(kind);
    command(m, data, 0.1, q, qd);
    CHECK(data.v_feedforward == Eigen::Vector2d(3.0, -4.0));
    CHECK(data.voltage == pd + Eigen::Vector2d(3.0, -4.0));
  }
}

TEST_CASE("command without motors: the input profile is the joint torque, in data.actuation") {
  Model m = two_servos(MotorModel::none);
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  finalize(m);
  Data data(m);
  command(m, data, 0.25, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero());
  CHECK(data.actuation == Eigen::Vector2d(m.inputs.joints[0].at(0.25), m.inputs.joints[1].at(0.25)));
  CHECK(data.voltage.isZero());  // no voltage without motors
}

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

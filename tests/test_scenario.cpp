// Scenario loader: YAML text -> validated Model, overrides, and the shipped
// scenes. The error cases are in test_scenario_errors.cpp, elbows/table/contact
// in test_scenario_contact.cpp; the shared fixtures in test_scenario_helpers.hpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "app/scenario/scenario.hpp"
#include "test_scenario_helpers.hpp"

using elbowsim::load_scenario;
using elbowsim::MotorModel;
using elbowsim::Scenario;
using elbowsim::ScenarioError;
using namespace scenario_test;

// ---------------------------------------------------------------------------
// Valid scenarios

TEST_CASE("planar shorthand fills joints and links as model.hpp describes") {
  Scenario s = load(kTwoLink);
  const elbowsim::Model& m = s.model;
  REQUIRE(m.dof == 2);
  CHECK(m.name == "two_link");
  CHECK(s.file == "x.yaml");

  // Joint 0 at the base, joint 1 at the tip of link 0; axes along -y.
  CHECK(approx(m.joints[0].origin_position, Eigen::Vector3d::Zero()));
  CHECK(approx(m.joints[1].origin_position, Eigen::Vector3d(0.3, 0, 0)));
  for (const auto& j : m.joints) {
    CHECK(approx(j.axis, Eigen::Vector3d(0, -1, 0)));
    CHECK(approx(j.origin_rotation, Eigen::Matrix3d::Identity()));
  }

  // Link 0: defaults com = l/2, I = m l^2/12, r = 0.02.
  const double i0 = 1.0 * 0.3 * 0.3 / 12;
  CHECK(approx(m.links[0].com, Eigen::Vector3d(0.15, 0, 0)));
  CHECK(approx(m.links[0].inertia,
               Eigen::Vector3d(1.0 * 0.02 * 0.02 / 2, i0, i0).asDiagonal().toDenseMatrix()));
  CHECK(m.links[0].radius == doctest::Approx(0.02));
  CHECK(approx(m.links[0].tip, Eigen::Vector3d(0.3, 0, 0)));

  // Link 1: everything given.
  CHECK(m.links[1].mass == doctest::Approx(0.5));
  CHECK(approx(m.links[1].com, Eigen::Vector3d(0.08, 0, 0)));
  CHECK(approx(m.links[1].inertia,
               Eigen::Vector3d(0.5 * 0.03 * 0.03 / 2, 0.002, 0.002).asDiagonal().toDenseMatrix()));
  CHECK(approx(m.links[1].tip, Eigen::Vector3d(0.2, 0, 0)));

  // Hand: the tip of the last link.
  CHECK(m.hand_link == 1);
  CHECK(approx(m.hand_point, Eigen::Vector3d(0.2, 0, 0)));
}

TEST_CASE("defaults of every optional section") {
  Scenario s = load(kTwoLink);
  const elbowsim::Model& m = s.model;
  CHECK(s.description.empty());
  CHECK(approx(m.base.matrix(), Eigen::Matrix4d::Identity()));
  CHECK(approx(m.gravity, Eigen::Vector3d(0, 0, -9.81)));
  CHECK(approx(m.damping, Eigen::Vector2d::Zero()));
  CHECK(m.effects.gravity);
  CHECK(m.effects.damping);
  CHECK(m.effects.rotor_inertia);
  CHECK(m.effects.motor == MotorModel::full);
  CHECK(m.options.duration == doctest::Approx(1.0));
  CHECK(m.options.step == doctest::Approx(1e-3));
  CHECK(m.options.integrator == elbowsim::IntegratorKind::rk4);  // auto's choice here
  CHECK(m.options.integrator_reason.starts_with("rk4 is stable at 1.5 times the step"));
  CHECK(m.options.dynamics == elbowsim::DynamicsMethod::crba);
  // The built-in motor: a 24 V, 20 W class servo behind 100:1, rated 1 A.
  REQUIRE(m.motors.size() == 2);
  CHECK(m.motors[1].builtin);
  CHECK(m.motors[1].resistance == doctest::Approx(2.0));
  CHECK(m.motors[1].inductance == doctest::Approx(0.5e-3));
  CHECK(m.motors[1].torque_constant == doctest::Approx(0.03));
  CHECK(m.motors[1].gear_ratio == doctest::Approx(100));
  CHECK(m.motors[1].rotor_inertia == doctest::Approx(5e-7));
  CHECK(m.motors[1].gear_friction == 0);
  CHECK(m.motors[1].voltage_limit == doctest::Approx(24.0));
  CHECK(m.motors[1].rated_current == doctest::Approx(1.0));
  CHECK(m.inputs.quantity == elbowsim::OpenLoopInputs::Quantity::voltage);
  CHECK(m.inputs.joints.empty());
  CHECK(approx(s.model.initial.q, Eigen::Vector2d::Zero()));
  CHECK(approx(s.model.initial.qd, Eigen::Vector2d::Zero()));
  CHECK(approx(s.model.initial.current, Eigen::Vector2d::Zero()));
  CHECK(s.output.folder == "runs/two_link");
  CHECK(s.output.trajectory);
  CHECK(s.output.summary);
  CHECK(s.output.every == 1);
  // finalize() ran: derived members are sized.
  CHECK(m.km.size() == 2);
}

TEST_CASE("general joints: origins, normalized axes, full inertia, base pose, hand") {
  Scenario s = load(yaml(R"(
name: general
description: two joints in space
robot:
  base: {xyz: [0.1, 0.2, 0.3], rpy: [0.1, 0.2, 0.3]}
  joints:
    - axis: [0, 0, 2]
      link:
        mass: 2.0
        com: [0.1, 0, 0]
        inertia: {ixx: 0.01, iyy: 0.02, izz: 0.025, ixy: 0.001}
        tip: [0.3, 0, 0]
    - origin: {xyz: [0.3, 0, 0], rpy: [1.5707963267948966, 0, 0]}
      axis: [0, 3, 4]
      link: {mass: 1.0, inertia: {ixx: 0.01, iyy: 0.01, izz: 0.01}, radius: 0.05}
  hand: {link: 0, point: [0.1, 0.2, 0.3]}
simulation: {duration: 0.5, step: 0.01, integrator: euler, dynamics: aba}
)"));
  const elbowsim::Model& m = s.model;
  REQUIRE(m.dof == 2);
  CHECK(s.description == "two joints in space");

  // Base: R = Rz(yaw) Ry(pitch) Rx(roll).
  Eigen::Matrix3d r = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
  CHECK(approx(m.base.linear(), r));
  CHECK(approx(m.base.translation(), Eigen::Vector3d(0.1, 0.2, 0.3)));

  CHECK(approx(m.joints[0].axis, Eigen::Vector3d(0, 0, 1)));
  CHECK(approx(m.joints[1].axis, Eigen::Vector3d(0, 0.6, 0.8)));
  CHECK(approx(m.joints[1].origin_position, Eigen::Vector3d(0.3, 0, 0)));
  Eigen::Matrix3d rx;
  rx << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  CHECK(approx(m.joints[1].origin_rotation, rx));

  Eigen::Matrix3d inertia;
  inertia << 0.01, 0.001, 0, 0.001, 0.02, 0, 0, 0, 0.025;
  CHECK(approx(m.links[0].inertia, inertia));
  CHECK(approx(m.links[0].com, Eigen::Vector3d(0.1, 0, 0)));
  CHECK(approx(m.links[0].tip, Eigen::Vector3d(0.3, 0, 0)));
  CHECK(approx(m.links[1].tip, Eigen::Vector3d::Zero()));
  CHECK(m.links[1].radius == doctest::Approx(0.05));

  CHECK(m.hand_link == 0);
  CHECK(approx(m.hand_point, Eigen::Vector3d(0.1, 0.2, 0.3)));
  CHECK(m.options.integrator == elbowsim::IntegratorKind::euler);
  CHECK(m.options.dynamics == elbowsim::DynamicsMethod::aba);
  CHECK(m.options.step == doctest::Approx(0.01));
}

TEST_CASE("motors: default, per-joint overrides, reflected constants") {
  Scenario s = load(two_link_with(R"(
motors:
  default: {resistance: 2.0, torque_constant: 0.03, gear_ratio: 100, rotor_inertia: 5e-7}
  joints:
    - {}
    - {resistance: 3.0, gear_friction: 1e-6}
effects: {motor: quasi_static}
)"));
  const elbowsim::Model& m = s.model;
  CHECK(m.effects.motor == MotorModel::quasi_static);
  CHECK(m.motors[0].resistance == doctest::Approx(2.0));
  CHECK(m.motors[1].resistance == doctest::Approx(3.0));
  CHECK(m.motors[1].torque_constant == doctest::Approx(0.03));
  CHECK(m.motors[1].gear_friction == doctest::Approx(1e-6));
  CHECK(m.motors[0].inductance == doctest::Approx(0.5e-3));  // the built-in motor's
  // Given constants make it the scene's own motor: not the built-in one, unrated.
  CHECK_FALSE(m.motors[0].builtin);
  CHECK(std::isinf(m.motors[0].rated_current));
  CHECK(m.km[0] == doctest::Approx(3.0));         // K k
  CHECK(m.armature[1] == doctest::Approx(5e-3));  // Im k^2
}

TEST_CASE("effects, damping, gravity, initial state and output") {
  Scenario s = load(two_link_with(R"(
effects: {gravity: false, damping: true, motor: full, rotor_inertia: false}
gravity: [0, 0, -1.62]
initial:
  q_deg: [90, -45]
  qd: [0.1, 0.2]
  current: [0.5, -0.5]
output: {folder: out/here, trajectory: false, summary: true, every: 10}
)"));
  const elbowsim::Model& m = s.model;
  CHECK_FALSE(m.effects.gravity);
  CHECK_FALSE(m.effects.rotor_inertia);
  CHECK(approx(m.gravity, Eigen::Vector3d(0, 0, -1.62)));
  CHECK(approx(s.model.initial.q, Eigen::Vector2d(std::numbers::pi / 2, -std::numbers::pi / 4)));
  CHECK(approx(s.model.initial.qd, Eigen::Vector2d(0.1, 0.2)));
  CHECK(approx(s.model.initial.current, Eigen::Vector2d(0.5, -0.5)));
  CHECK(s.output.folder == "out/here");
  CHECK_FALSE(s.output.trajectory);
  CHECK(s.output.every == 10);

  // Damping: one number for all joints, or one per joint.
  const std::string base = kTwoLink;
  std::string one = base;
  one.replace(one.find("simulation:"), 0, "  damping: 0.5\n");
  CHECK(approx(load(one).model.damping, Eigen::Vector2d(0.5, 0.5)));
  std::string list = base;
  list.replace(list.find("simulation:"), 0, "  damping: [0.1, 0.2]\n");
  CHECK(approx(load(list).model.damping, Eigen::Vector2d(0.1, 0.2)));
}

TEST_CASE("inputs: profile kinds, list and map forms") {
  Scenario s = load(two_link_with(R"(
inputs:
  voltage:
    - {type: sine, amplitude: 1.0, frequency: 0.5, phase: 0.1, offset: 2.0}
    - {type: table, times: [0, 1, 2], values: [0, 3, 0]}
)"));
  const auto& in = s.model.inputs;
  REQUIRE(in.joints.size() == 2);
  CHECK(in.quantity == elbowsim::OpenLoopInputs::Quantity::voltage);
  CHECK(in.joints[0].kind == elbowsim::InputProfile::Kind::sine);
  CHECK(in.joints[0].offset == doctest::Approx(2.0));
  CHECK(in.joints[1].at(0.5) == doctest::Approx(1.5));

  // Map form: the joints not named get zero; torque inputs without a motor.
  Scenario t = load(two_link_with(R"(
effects: {motor: none}
inputs:
  torque:
    1: {type: steps, times: [0, 1], values: [2, -2]}
)"));
  const auto& tin = t.model.inputs;
  REQUIRE(tin.joints.size() == 2);
  CHECK(tin.quantity == elbowsim::OpenLoopInputs::Quantity::torque);
  CHECK(tin.joints[0].kind == elbowsim::InputProfile::Kind::zero);
  CHECK(tin.joints[1].at(1.5) == doctest::Approx(-2.0));

  Scenario c = load(two_link_with(R"(
inputs: {voltage: [{type: constant, value: 2.0}, {type: zero}]}
)"));
  CHECK(c.model.inputs.joints[0].at(3.0) == doctest::Approx(2.0));
}

// ---------------------------------------------------------------------------
// Overrides

TEST_CASE("overrides replace values, add keys and remove sections") {
  Scenario s =
      load(kTwoLink, {"simulation.step=1e-4", "effects.motor=none", "robot.planar.links[0].mass=2",
                      "output.every=5", "robot.planar.links[1]={length: 0.4, mass: 3}"});
  CHECK(s.model.options.step == doctest::Approx(1e-4));
  CHECK(s.model.effects.motor == MotorModel::none);
  CHECK(s.model.links[0].mass == doctest::Approx(2.0));
  CHECK(s.model.links[1].mass == doctest::Approx(3.0));
  CHECK(approx(s.model.links[1].tip, Eigen::Vector3d(0.4, 0, 0)));
  CHECK(s.output.every == 5);

  // "inputs=" sets inputs to nothing, so a voltage scenario can run motor: none.
  std::string with_voltage = two_link_with("inputs: {voltage: [{type: zero}, {type: zero}]}\n");
  CHECK_THROWS_AS(load(with_voltage, {"effects.motor=none"}), ScenarioError);
  CHECK(load(with_voltage, {"effects.motor=none", "inputs="}).model.inputs.joints.empty());

  // Overrides do not touch the text they came from: the same text loads as before.
  CHECK(load(kTwoLink).model.links[0].mass == doctest::Approx(1.0));
}

TEST_CASE("a bad override is named in the message") {
  CHECK(error_of(kTwoLink, {"simulation.step=abc"}) ==
        "command line --set simulation.step=abc: simulation.step: expected a number (got \"abc\")");
  try {
    load(kTwoLink, {"simulation.step=abc"});
    FAIL("expected an error");
  } catch (const ScenarioError& e) {
    CHECK(e.file == "command line --set simulation.step=abc");
    CHECK(e.key == "simulation.step");
    CHECK(e.line == 0);
    CHECK(e.column == 0);
  }
  std::string msg = error_of(kTwoLink, {"simulation.stpe=1"});
  CHECK(msg.starts_with("command line --set simulation.stpe=1: simulation.stpe: unknown key"));
  CHECK(contains(msg, "did you mean \"step\""));
  CHECK(error_of(kTwoLink, {"robot.planar.links[0].mass=-1"}) ==
        "command line --set robot.planar.links[0].mass=-1: robot.planar.links[0].mass: "
        "must be > 0 (got -1)");
  CHECK(contains(error_of(kTwoLink, {"robot.planar.links[5].mass=1"}),
                 "index out of range (the list has 2 items)"));
  CHECK(contains(error_of(kTwoLink, {"initial.q=[0.5]", "initial.q[3]=1"}),
                 "index out of range (the list has 1 item)"));
  CHECK(contains(error_of(kTwoLink, {"simulation.step"}), "expected key.path=value"));
  CHECK(contains(error_of(kTwoLink, {"name.x=1"}), "name is not a map"));
  CHECK(contains(error_of(kTwoLink, {"simulation.step=[1,"}), "invalid YAML value"));
  // Errors in values the override did not set still point at the file.
  CHECK(error_of(kTwoLink, {"simulation.duration=1e-4"})
            .starts_with("command line --set simulation.duration=1e-4: simulation.duration:"));
}

// ---------------------------------------------------------------------------
// The shipped scenarios load.

TEST_CASE("shipped scenarios load") {
  Scenario pendulum = load_scenario((scenarios_dir() / "two_link_pendulum.yaml").string());
  CHECK(pendulum.model.dof == 2);
  CHECK(pendulum.model.effects.motor == MotorModel::none);
  CHECK(approx(pendulum.model.initial.q, Eigen::Vector2d(0.5, 0.3)));

  Scenario arm = load_scenario((scenarios_dir() / "default.yaml").string());
  CHECK(arm.model.dof == 4);
  CHECK(arm.model.effects.motor == MotorModel::full);
  CHECK(arm.model.inputs.joints.size() == 4);
  CHECK(arm.output.every == 10);
  CHECK(arm.model.km[0] == doctest::Approx(3.0));
}

TEST_CASE("joint_friction: one number for every joint or one per joint; breakaway defaults to Coulomb") {
  const Scenario s = load(two_link_with(R"(
effects: {joint_friction: true}
joint_friction: {coulomb: 0.1, breakaway: [0.2, 0.15]}
)"));
  REQUIRE(s.model.joint_friction.size() == 2);
  CHECK(s.model.joint_friction[0].coulomb == 0.1);
  CHECK(s.model.joint_friction[1].breakaway == 0.15);
  CHECK(s.model.joint_friction[1].stribeck_velocity == 0.01);
  const Scenario plain = load(two_link_with("effects: {joint_friction: true}\njoint_friction: {coulomb: 0.3}\n"));
  CHECK(plain.model.joint_friction[0].breakaway == 0.3);
  CHECK(load(kTwoLink).model.joint_friction.empty());
}

TEST_CASE("joint_friction errors") {
  CHECK_ERROR(two_link_with("joint_friction: {coulomb: 0.1}\n"), "x.yaml:9:", "joint_friction",
              "needs effects.joint_friction: true");
  CHECK_ERROR(two_link_with("effects: {joint_friction: true}\n"), "x.yaml:9:", "effects.joint_friction",
              "needs a joint_friction section");
  CHECK_ERROR(two_link_with("effects: {joint_friction: true}\njoint_friction: {coulomb: 0.2, breakaway: 0.1}\n"),
              "x.yaml:10:", "joint_friction.breakaway", "must be >= coulomb");
  CHECK_ERROR(two_link_with("effects: {joint_friction: true}\njoint_friction: {coulomb: [0.1]}\n"),
              "x.yaml:10:", "joint_friction.coulomb", "one per joint");
  CHECK_ERROR(two_link_with("effects: {joint_friction: true}\njoint_friction: {stribeck_velocity: 0}\n"),
              "x.yaml:10:", "joint_friction.stribeck_velocity", "must be > 0");
}

TEST_CASE("springs: a list of torsion springs at joints; absent or null, none; the effects list names them") {
  const Scenario s = load(two_link_with(R"(
springs:
  - {joint: 0, torque: 9.3, stiffness: 5.8, at: 0.6}
  - {joint: 1, torque: -2}
)"));
  REQUIRE(s.model.springs.size() == 2);
  CHECK(s.model.springs[0].torque == 9.3);
  CHECK(s.model.springs[0].stiffness == 5.8);
  CHECK(s.model.springs[0].at == 0.6);
  CHECK(s.model.springs[1].joint == 1);
  CHECK(s.model.springs[1].stiffness == 0.0);  // a constant-torque spring
  const auto effects = s.model.active_effects();
  CHECK(std::find(effects.begin(), effects.end(), "springs") != effects.end());
  CHECK(load(kTwoLink).model.springs.empty());
  CHECK(load(two_link_with("springs: [{joint: 0, torque: 1}]\n"), {"springs=null"}).model.springs.empty());
}

TEST_CASE("springs errors name the line and key") {
  CHECK_ERROR(two_link_with("springs: [{joint: 2, torque: 1}]\n"), "x.yaml:9:", "springs[0].joint",
              "must be a joint of the arm, 0 .. 1");
  CHECK_ERROR(two_link_with("springs: [{joint: shoulder, torque: 1}]\n"), "x.yaml:9:", "springs[0].joint",
              "names no joint of the arm (give an index, 0 .. 1)");
  CHECK_ERROR(two_link_with("springs: [{joint: 0}]\n"), "x.yaml:9:", "springs[0].torque", "required key is missing");
  CHECK_ERROR(two_link_with("springs: [{joint: 0, torque: 1, stiffness: -3}]\n"), "x.yaml:9:",
              "springs[0].stiffness", ">= 0");
  CHECK_ERROR(two_link_with("springs: [{joint: 0, torque: 1, rate: 3}]\n"), "x.yaml:9:", "springs[0].rate",
              "unknown key");
}

TEST_CASE("motors: gear efficiencies in (0, 1]; below 1 the model keeps a gear loss") {
  const Scenario s = load(two_link_with("motors: {default: {efficiency: 0.85, backdrive_efficiency: 0.6}}\n"));
  CHECK(s.model.motors[1].efficiency == 0.85);
  CHECK(s.model.gear_efficiency[0] == 0.85);
  CHECK(s.model.backdrive_efficiency[1] == 0.6);
  CHECK(s.model.gear_losses);
  CHECK_FALSE(load(kTwoLink).model.gear_losses);
  CHECK_ERROR(two_link_with("motors: {default: {efficiency: 1.2}}\n"), "x.yaml:9:",
              "motors.default.efficiency", "must be in (0, 1]");
  CHECK_ERROR(two_link_with("motors: {default: {backdrive_efficiency: 0}}\n"), "x.yaml:9:",
              "motors.default.backdrive_efficiency", "must be in (0, 1]");
}

TEST_CASE("motors: a joint given none of the motor's constants runs the rated built-in motor") {
  auto motors = [](const char* section) { return load(two_link_with(section)).model.motors; };
  // No section, or only what does not change the motor (voltage, amplifier,
  // gear losses): the built-in motor with its 1 A rating, or the one given.
  for (const char* section : {"", "motors: {default: {voltage_limit: 12, current_limit: 5}}\n"}) {
    CAPTURE(section);
    for (const elbowsim::Motor& m : motors(section)) {
      CHECK(m.builtin);
      CHECK(m.rated_current == doctest::Approx(elbowsim::kBuiltinRatedCurrent));
    }
  }
  CHECK(motors("motors: {default: {rated_current: 2}}\n")[1].rated_current == doctest::Approx(2));
  // Any of resistance, inductance, torque_constant, gear_ratio, rotor_inertia
  // names the joint's own motor: unrated unless it says so.
  const auto own = motors("motors: {joints: [{gear_ratio: 50}, {}]}\n");
  CHECK_FALSE(own[0].builtin);
  CHECK(std::isinf(own[0].rated_current));
  CHECK(own[1].builtin);
  CHECK(own[1].rated_current == doctest::Approx(1.0));
  const auto rated = motors("motors: {default: {resistance: 3, rated_current: 0.5}}\n");
  CHECK_FALSE(rated[1].builtin);
  CHECK(rated[1].rated_current == doctest::Approx(0.5));
}

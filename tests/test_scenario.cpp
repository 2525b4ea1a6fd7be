// Scenario loader: YAML text -> validated Model, and errors that name file,
// line, column and key path (STYLE.md §6). Each fixture is a small scenario;
// line numbers in the checks count from the fixture's first line.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "app/scenario/scenario.hpp"

using elbowsim::load_scenario;
using elbowsim::load_scenario_text;
using elbowsim::MotorModel;
using elbowsim::Scenario;
using elbowsim::ScenarioError;

namespace {

// Fixtures are written as R"(\n...)": drop the first newline so that the
// first line of the text is line 1.
std::string yaml(const char* text) {
  std::string s(text);
  return s.starts_with('\n') ? s.substr(1) : s;
}

Scenario load(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return load_scenario_text(text, "x.yaml", overrides);
}

// The error message of loading `text`, or "" if it loads.
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    load(text, overrides);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

bool approx(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double atol = 1e-12) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a - b).cwiseAbs().maxCoeff() <= atol;
}

// Checks that loading `text` fails at `location` ("x.yaml:7:" or
// "x.yaml:7:12:") naming `key`, with `words` in the message.
#define CHECK_ERROR(text, location, key, words)              \
  do {                                                       \
    const std::string msg_ = error_of(text);                 \
    INFO("message: " << msg_);                               \
    CHECK(msg_.starts_with(location));                       \
    CHECK(contains(msg_, std::string(": ") + (key) + ": ")); \
    CHECK(contains(msg_, words));                            \
  } while (0)

// Two planar links; the second overrides every default.
//
//   z
//   |      link 1 (0.2 m)
//   |    o------o hand
//   |   / link 0 (0.3 m)
//   o------ x
const std::string kTwoLink = yaml(R"(
name: two_link
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 0.5, com: 0.08, inertia: 0.002, radius: 0.03}
simulation:
  duration: 1.0
)");

// The planar arm with `lines` appended (top-level sections).
std::string two_link_with(const char* lines) { return kTwoLink + yaml(lines); }

std::filesystem::path scenarios_dir() {
  return std::filesystem::path(__FILE__).parent_path().parent_path() / "scenarios";
}

}  // namespace

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
  CHECK(m.options.integrator == elbowsim::IntegratorKind::rk4);
  CHECK(m.options.dynamics == elbowsim::DynamicsMethod::crba);
  REQUIRE(m.motors.size() == 2);
  CHECK(m.motors[1].resistance == doctest::Approx(1.0));
  CHECK(m.motors[1].inductance == doctest::Approx(1e-3));
  CHECK(m.motors[1].torque_constant == doctest::Approx(0.05));
  CHECK(m.motors[1].voltage_limit == doctest::Approx(24.0));
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
  CHECK(m.motors[0].inductance == doctest::Approx(1e-3));
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
  CHECK(contains(error_of(kTwoLink, {"robot.planar.links[5].mass=1"}), "index out of range"));
  CHECK(contains(error_of(kTwoLink, {"simulation.step"}), "expected key.path=value"));
  CHECK(contains(error_of(kTwoLink, {"name.x=1"}), "name is not a map"));
  CHECK(contains(error_of(kTwoLink, {"simulation.step=[1,"}), "invalid YAML value"));
  // Errors in values the override did not set still point at the file.
  CHECK(error_of(kTwoLink, {"simulation.duration=1e-4"})
            .starts_with("command line --set simulation.duration=1e-4: simulation.duration:"));
}

// ---------------------------------------------------------------------------
// Bad input: one case per class, each naming line, column and key path.

TEST_CASE("error: the message format") {
  const std::string text = yaml(R"(
name: two_link
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: -1}
simulation:
  duration: 1.0
)");
  CHECK(error_of(text) == "x.yaml:6:29: robot.planar.links[1].mass: must be > 0 (got -1)");
  try {
    load(text);
  } catch (const ScenarioError& e) {
    CHECK(e.file == "x.yaml");
    CHECK(e.line == 6);
    CHECK(e.column == 29);
    CHECK(e.key == "robot.planar.links[1].mass");
  }
}

TEST_CASE("error: unknown keys, with a suggestion") {
  CHECK_ERROR(yaml(R"(
name: two_link
robot:
  planar:
    links:
      - length: 0.3
        mas: 1.0
simulation: {duration: 1}
)"),
              "x.yaml:6:9:", "robot.planar.links[0].mas", "did you mean \"mass\"");
  CHECK_ERROR(two_link_with("simulaton_extra: 1\n"), "x.yaml:9:1:", "simulaton_extra",
              "unknown key");
  CHECK_ERROR(two_link_with("simulation_: 1\n"), "x.yaml:9:", "simulation_",
              "did you mean \"simulation\"");
  CHECK_ERROR(two_link_with("effects: {gravty: false}\n"), "x.yaml:9:", "effects.gravty",
              "did you mean \"gravity\"");
}

TEST_CASE("error: duplicate keys") {
  CHECK_ERROR(two_link_with("gravity: [0, 0, -9.81]\ngravity: [0, 0, -1]\n"),
              "x.yaml:10:1:", "gravity", "duplicate key (first at line 9)");
}

TEST_CASE("error: wrong types") {
  CHECK_ERROR(two_link_with("gravity: [0, 0, down]\n"), "x.yaml:9:17:", "gravity[2]",
              "expected a number (got \"down\")");
  CHECK_ERROR(two_link_with("gravity: [0, -9.81]\n"), "x.yaml:9:10:", "gravity",
              "expected a list of 3 numbers (x, y, z) (got 2)");
  CHECK_ERROR(two_link_with("gravity: \"-9.81\"\n"), "x.yaml:9:", "gravity", "expected a list");
  CHECK_ERROR(two_link_with("effects: {gravity: yes please}\n"), "x.yaml:9:", "effects.gravity",
              "expected true or false");
  CHECK_ERROR(two_link_with("output: {every: \"10\"}\n"), "x.yaml:9:", "output.every",
              "expected a whole number");
  CHECK_ERROR(two_link_with("output: {every: 2.5}\n"), "x.yaml:9:", "output.every",
              "expected a whole number");
  CHECK_ERROR(two_link_with("effects: [gravity]\n"), "x.yaml:9:", "effects", "expected a map");
  CHECK_ERROR(two_link_with("initial: {q: \"0.1\"}\n"), "x.yaml:9:", "initial.q",
              "expected a list of 2 numbers");
}

TEST_CASE("error: quoted numbers are strings") {
  CHECK_ERROR(two_link_with("initial: {q: [0, '0.5']}\n"), "x.yaml:9:", "initial.q[1]",
              "expected a number (got the string \"0.5\")");
}

TEST_CASE("error: missing required keys point at the parent map") {
  CHECK_ERROR(yaml(R"(
name: two_link
robot:
  planar:
    links:
      - {length: 0.3}
simulation: {duration: 1}
)"),
              "x.yaml:5:9:", "robot.planar.links[0].mass", "required key is missing");
  CHECK_ERROR(yaml(R"(
name: two_link
robot:
  planar:
    links: [{length: 0.3, mass: 1}]
)"),
              "x.yaml:1:1:", "simulation", "required key is missing");
  CHECK_ERROR(yaml(R"(
name: two_link
robot:
  planar:
    links: [{length: 0.3, mass: 1}]
simulation:
  step: 0.001
)"),
              "x.yaml:6:3:", "simulation.duration", "required key is missing");
  CHECK(error_of(two_link_with("description:\n")).empty());  // a null optional key: default
}

TEST_CASE("error: non-finite numbers") {
  CHECK_ERROR(two_link_with("gravity: [0, 0, .inf]\n"), "x.yaml:9:17:", "gravity[2]",
              "must be a finite number (got .inf)");
  CHECK_ERROR(two_link_with("gravity: [0, 0, 1e999]\n"), "x.yaml:9:17:", "gravity[2]",
              "must be a finite number");
  CHECK_ERROR(two_link_with("gravity: [.nan, 0, 0]\n"), "x.yaml:9:", "gravity[0]",
              "must be a finite number");
}

TEST_CASE("error: link length, mass and radius must be positive") {
  CHECK_ERROR(yaml(R"(
name: a
robot:
  planar:
    links:
      - length: 0
        mass: 1
simulation: {duration: 1}
)"),
              "x.yaml:5:17:", "robot.planar.links[0].length", "must be > 0 (got 0)");
  CHECK_ERROR(yaml(R"(
name: a
robot:
  planar:
    links:
      - length: 1
        mass: 1
        radius: -0.1
simulation: {duration: 1}
)"),
              "x.yaml:7:17:", "robot.planar.links[0].radius", "must be > 0 (got -0.1)");
}

TEST_CASE("error: inertia not positive definite or not physical") {
  const char* general = R"(
name: a
robot:
  joints:
    - link:
        mass: 1
        inertia: {ixx: 0.01, iyy: 0.01, izz: %s}
simulation: {duration: 1}
)";
  auto with_izz = [&](const std::string& izz) {
    std::string text = yaml(general);
    return text.replace(text.find("%s"), 2, izz);
  };
  CHECK_ERROR(with_izz("-0.01"), "x.yaml:6:18:", "robot.joints[0].link.inertia",
              "must be positive definite");
  CHECK_ERROR(with_izz("0.03"), "x.yaml:6:18:", "robot.joints[0].link.inertia",
              "triangle inequality");
  CHECK(error_of(with_izz("0.02")).empty());  // a flat plate: ixx + iyy = izz exactly

  // Planar: diag(m r^2/2, I, I) needs I >= m r^2/4.
  CHECK_ERROR(two_link_with("").replace(kTwoLink.find("inertia: 0.002"), 14, "inertia: 1e-6"),
              "x.yaml:6:", "robot.planar.links[1].inertia", "is too small for the link's radius");
  const char* stubby = R"(
name: a
robot:
  planar:
    links:
      - {length: 0.01, mass: 1%s}
simulation: {duration: 1}
)";
  auto with = [&](const std::string& extra) {
    std::string text = yaml(stubby);
    return text.replace(text.find("%s"), 2, extra);
  };
  CHECK_ERROR(with(", radius: 0.1"), "x.yaml:5:41:", "robot.planar.links[0].radius",
              "is too large for the link");
  CHECK_ERROR(with(""), "x.yaml:5:9:", "robot.planar.links[0]", "too short for the default radius");
  CHECK(error_of(with(", radius: 0.001")).empty());
}

TEST_CASE("error: zero joint axis") {
  CHECK_ERROR(yaml(R"(
name: a
robot:
  joints:
    - axis: [0, 0, 0]
      link: {mass: 1, inertia: {ixx: 1, iyy: 1, izz: 1}}
simulation: {duration: 1}
)"),
              "x.yaml:4:13:", "robot.joints[0].axis", "non-zero");
}

TEST_CASE("error: both planar and joints, or neither") {
  CHECK_ERROR(yaml(R"(
name: a
robot:
  planar: {links: [{length: 1, mass: 1}]}
  joints: []
simulation: {duration: 1}
)"),
              "x.yaml:3:3:", "robot", "exactly one of planar or joints (got both)");
  CHECK_ERROR(yaml(R"(
name: a
robot:
  damping: 0.1
simulation: {duration: 1}
)"),
              "x.yaml:3:3:", "robot", "give exactly one of planar or joints");
  CHECK_ERROR(yaml(R"(
name: a
robot:
  planar: {links: []}
simulation: {duration: 1}
)"),
              "x.yaml:3:19:", "robot.planar.links", "at least one");
}

TEST_CASE("error: per-joint lists must have dof entries") {
  CHECK_ERROR(two_link_with("initial: {q: [0.1, 0.2, 0.3]}\n"), "x.yaml:9:", "initial.q",
              "expected a list of 2 numbers (one per joint) (got 3)");
  CHECK_ERROR(two_link_with("motors: {joints: [{}]}\n"), "x.yaml:9:", "motors.joints",
              "expected 2 entries, one per joint (got 1)");
  CHECK_ERROR(two_link_with("inputs: {voltage: [{type: zero}]}\n"), "x.yaml:9:", "inputs.voltage",
              "expected 2 profiles");
  std::string damping = kTwoLink;
  damping.replace(damping.find("simulation:"), 0, "  damping: [0.1]\n");
  CHECK_ERROR(damping, "x.yaml:7:12:", "robot.damping", "expected a list of 2 numbers");
  damping = kTwoLink;
  damping.replace(damping.find("simulation:"), 0, "  damping: [0.1, -0.2]\n");
  CHECK_ERROR(damping, "x.yaml:7:18:", "robot.damping[1]", "must be >= 0 (got -0.2)");
}

TEST_CASE("error: motor constants") {
  CHECK_ERROR(two_link_with("motors:\n  default: {inductance: -1e-3}\n"),
              "x.yaml:10:25:", "motors.default.inductance", "must be >= 0 (got -0.001)");
  CHECK_ERROR(two_link_with("motors:\n  default: {resistance: 0}\n"),
              "x.yaml:10:", "motors.default.resistance", "must be > 0 (got 0)");
  CHECK_ERROR(two_link_with("motors:\n  joints: [{}, {inductance: 0}]\n"),
              "x.yaml:10:", "motors.joints[1].inductance", "must be > 0 with effects.motor: full");
  // L = 0 is fine for the quasi-static model; a per-joint L > 0 lifts a default L = 0.
  CHECK(error_of(
            two_link_with("motors: {default: {inductance: 0}}\neffects: {motor: quasi_static}\n"))
            .empty());
  CHECK(error_of(
            two_link_with(
                "motors: {default: {inductance: 0}, joints: [{inductance: 1}, {inductance: 1}]}\n"))
            .empty());
  // Validated even when the motor is off.
  CHECK_ERROR(two_link_with("effects: {motor: none}\nmotors: {default: {gear_ratio: -3}}\n"),
              "x.yaml:10:", "motors.default.gear_ratio", "must be > 0");
}

TEST_CASE("error: step and duration") {
  CHECK_ERROR(yaml(R"(
name: a
robot: {planar: {links: [{length: 1, mass: 1}]}}
simulation:
  duration: 1
  step: 0
)"),
              "x.yaml:5:9:", "simulation.step", "must be > 0 (got 0)");
  CHECK_ERROR(yaml(R"(
name: a
robot: {planar: {links: [{length: 1, mass: 1}]}}
simulation:
  duration: 1
  step: 2
)"),
              "x.yaml:5:9:", "simulation.step", "must be <= simulation.duration");
  CHECK_ERROR(yaml(R"(
name: a
robot: {planar: {links: [{length: 1, mass: 1}]}}
simulation:
  duration: -1
)"),
              "x.yaml:4:13:", "simulation.duration", "must be > 0 (got -1)");
}

TEST_CASE("error: enumerations list the choices") {
  CHECK_ERROR(two_link_with("effects: {motor: ful}\n"), "x.yaml:9:18:", "effects.motor",
              "must be one of none, quasi_static, full (got \"ful\"; did you mean \"full\"?)");
  std::string rk5 = kTwoLink + "  integrator: rk5\n";
  CHECK_ERROR(rk5, "x.yaml:9:15:", "simulation.integrator", "did you mean \"rk4\"");
}

TEST_CASE("error: input profiles") {
  CHECK_ERROR(two_link_with(R"(
inputs:
  voltage:
    - {type: zero}
    - {type: table, times: [0, 2, 1], values: [0, 1, 2]}
)"),
              "x.yaml:12:35:", "inputs.voltage[1].times[2]", "strictly increasing");
  CHECK_ERROR(two_link_with(R"(
inputs:
  voltage:
    - {type: zero}
    - {type: steps, times: [0, 1], values: [1]}
)"),
              "x.yaml:12:44:", "inputs.voltage[1].values", "expected a list of 2 numbers");
  CHECK_ERROR(two_link_with(R"(
inputs:
  voltage:
    - {type: constant, amplitude: 1}
    - {type: zero}
)"),
              "x.yaml:11:24:", "inputs.voltage[0].amplitude", "unknown key");
  CHECK_ERROR(two_link_with(R"(
inputs:
  voltage:
    - {tpye: constant, value: 1}
    - {type: zero}
)"),
              "x.yaml:11:8:", "inputs.voltage[0].tpye", "did you mean \"type\"");
  CHECK_ERROR(two_link_with(R"(
inputs:
  voltage:
    2: {type: zero}
)"),
              "x.yaml:11:5:", "inputs.voltage.2", "joint index out of range");
}

TEST_CASE("error: voltage needs a motor, torque needs none") {
  CHECK_ERROR(two_link_with(R"(
effects: {motor: none}
inputs:
  voltage: [{type: zero}, {type: zero}]
)"),
              "x.yaml:11:12:", "inputs.voltage", "voltage inputs need a motor");
  CHECK_ERROR(two_link_with(R"(
inputs:
  torque: [{type: zero}, {type: zero}]
)"),
              "x.yaml:10:11:", "inputs.torque", "torque inputs need effects.motor: none");
  CHECK_ERROR(two_link_with(R"(
inputs:
  torque: [{type: zero}, {type: zero}]
  voltage: [{type: zero}, {type: zero}]
)"),
              "x.yaml:10:3:", "inputs", "not both");
}

TEST_CASE("error: hand, initial angles, name, output") {
  CHECK_ERROR(two_link_with("").replace(kTwoLink.find("simulation:"), 0, "  hand: {link: -3}\n"),
              "x.yaml:7:", "robot.hand.link", "out of range");
  CHECK(load(two_link_with("").replace(kTwoLink.find("simulation:"), 0, "  hand: {link: -2}\n"))
            .model.hand_link == 0);
  CHECK_ERROR(two_link_with("initial: {q: [0, 0], q_deg: [0, 0]}\n"), "x.yaml:9:", "initial.q_deg",
              "either q or q_deg");
  std::string bad_name = kTwoLink;
  bad_name.replace(0, 14, "name: two link");
  CHECK_ERROR(bad_name, "x.yaml:1:7:", "name", "letters, digits");
  CHECK_ERROR(two_link_with("output: {every: 0}\n"), "x.yaml:9:", "output.every",
              "must be >= 1 (got 0)");
}

TEST_CASE("error: YAML syntax and files") {
  std::string msg = error_of("name: a\nrobot: [1, 2\n");
  CHECK(msg.starts_with("x.yaml:"));
  CHECK(contains(msg, "invalid YAML"));
  CHECK(contains(error_of("- 1\n- 2\n"), "expected a map of sections"));
  CHECK_THROWS_WITH_AS(load_scenario("/nonexistent/x.yaml"),
                       doctest::Contains("/nonexistent/x.yaml: cannot open"), ScenarioError);
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

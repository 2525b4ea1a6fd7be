// Scenario loader, bad input: one case per class of error, each naming file,
// line, column and key path, so a user can find the mistake. Fixtures and CHECK_ERROR are in
// test_scenario_helpers.hpp; line numbers count from the fixture's first line.
#include <doctest/doctest.h>

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
              "x.yaml:1:1:", "simulation", "is required without a task");
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

TEST_CASE("error: the error-control keys belong to the adaptive integrators") {
  auto with = [](const char* extra) {
    return yaml((std::string(R"(
name: two_link
robot:
  planar:
    links: [{length: 0.3, mass: 1}]
simulation:
  duration: 1
)") + extra).c_str());
  };
  CHECK_ERROR(with("  integrator: rk4\n  rtol: 1e-6\n"), "x.yaml:8:", "simulation.rtol",
              "applies to the adaptive integrators only (dopri5, ros34pw2); rk4 takes a fixed");
  // Without an integrator, auto decides first: rk4 here (the built-in motor's
  // L/R = 0.25 ms is resolved at 1 ms), so rtol is refused; on a winding
  // 1000 times faster it chooses ros34pw2, and rtol steers it.
  CHECK_ERROR(with("  rtol: 1e-6\n"), "x.yaml:7:", "simulation.rtol",
              "simulation.integrator auto chose rk4, which takes a fixed simulation.step");
  CHECK(error_of(with("  rtol: 1e-6\nmotors: {default: {inductance: 5.0e-7}}\n")).empty());
  CHECK_ERROR(with("  integrator: euler\n  max_step: 0.01\n"), "x.yaml:8:", "simulation.max_step",
              "adaptive integrators only");
  CHECK_ERROR(with("  integrator: dopri5\n  rtol: 1e-16\n"), "x.yaml:8:", "simulation.rtol",
              "must be >= 1e-14");
  CHECK_ERROR(with("  integrator: ros34pw2\n  atol: -1\n"), "x.yaml:8:", "simulation.atol", "must be");
  CHECK(error_of(with("  integrator: dopri5\n  rtol: 1e-8\n  atol: 1e-10\n")).empty());
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
              "x.yaml:3:3:", "robot", "exactly one of planar, joints or urdf (got 2)");
  CHECK_ERROR(yaml(R"(
name: a
robot:
  damping: 0.1
simulation: {duration: 1}
)"),
              "x.yaml:3:3:", "robot", "give exactly one of planar, joints or urdf");
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
  // One joint: counted in the singular.
  const std::string one_link = yaml(R"(
name: a
robot: {planar: {links: [{length: 1, mass: 1}]}}
simulation: {duration: 1}
)");
  CHECK_ERROR(one_link + "initial: {q: [0.1, 0.2]}\n", "x.yaml:4:", "initial.q",
              "expected a list of 1 number (one per joint) (got 2)");
  CHECK_ERROR(one_link + "motors: {joints: [{}, {}]}\n", "x.yaml:4:", "motors.joints",
              "expected 1 entry, one per joint (got 2)");
  CHECK_ERROR(one_link + "inputs: {voltage: [{type: zero}, {type: zero}]}\n",
              "x.yaml:4:", "inputs.voltage", "expected 1 profile, one per joint (got 2)");
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

TEST_CASE("error: more joints than supported is an error before any entry is read") {
  // A 20 000-link arm (a hand-made input run through tests/fuzz/) made the loader
  // ask for 12.8 GB (dense dof x dof matrices for the initial-penetration check):
  // the count is checked first.
  auto planar = [](int n) {
    std::string text = "name: long_arm\nrobot:\n  planar:\n    links:\n";
    for (int i = 0; i < n; ++i) text += "      - {length: 0.1, mass: 0.1, radius: 0.005}\n";
    return text + "simulation:\n  duration: 1.0\n";
  };
  CHECK(load(planar(elbowsim::kMaxJoints)).model.dof == elbowsim::kMaxJoints);
  CHECK(error_of(planar(elbowsim::kMaxJoints + 1)) ==
        "x.yaml:5:7: robot.planar.links: has 257 entries; at most 256 joints are supported");
  std::string joints = "name: long_arm\nrobot:\n  joints:\n";
  for (int i = 0; i <= elbowsim::kMaxJoints; ++i)
    joints += "    - {link: {mass: 1, inertia: {ixx: 1, iyy: 1, izz: 1}}}\n";
  joints += "simulation:\n  duration: 1.0\n";
  CHECK(error_of(joints) == "x.yaml:4:5: robot.joints: has 257 entries; at most 256 joints are supported");
}

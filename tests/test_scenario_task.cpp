// Scenario loader: task, controller and hand_load (the paper's experiment),
// the Model members they fill (Model::task / controller / hand_load), and
// their errors. Fixtures and CHECK_ERROR are in test_scenario_helpers.hpp;
// kTwoLink has 8 lines, so sections appended with two_link_with() start at
// line 9 (kScene below: at line 12).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/control/plan.hpp"
#include "test_scenario_helpers.hpp"

using elbowsim::ControllerSpec;
using elbowsim::HandTask;
using elbowsim::Model;
using namespace scenario_test;

namespace {

// The two-link arm with an elbow at the end of link 0 and a table 0.15 m
// below the arm (q = 0: the arm lies along x at z = 0). Lines 9-11.
const std::string kScene = two_link_with(R"(
effects: {contact: true}
elbows: [{name: elbow, link: 0, at: 0.3}]
table: {boxes: [{center: [0.4, 0, -0.2], size: [1.0, 0.6, 0.1]}]}
)");

std::string scene_with(const char* lines) { return kScene + yaml(lines); }

// A task that keeps the elbow on the table (or at a clearance above it) takes
// one joint of a planar arm for it, and the hand needs two more: three links
// (start_checks.hpp refuses the two-link arm with "the plan could only miss").
const std::string kThreeLinkScene = yaml(R"(
name: three_link
robot:
  planar:
    links:
      - {length: 0.3, mass: 1.0}
      - {length: 0.2, mass: 0.5, com: 0.08, inertia: 0.002, radius: 0.03}
      - {length: 0.1, mass: 0.2}
simulation:
  duration: 1.0
effects: {contact: true}
elbows: [{name: elbow, link: 0, at: 0.3}]
table: {boxes: [{center: [0.4, 0, -0.2], size: [1.0, 0.6, 0.1]}]}
)");

std::string three_link_with(const char* lines) { return kThreeLinkScene + yaml(lines); }

}  // namespace

// ---------------------------------------------------------------------------
// Valid scenes

TEST_CASE("task: defaults without the sections") {
  const Scenario m = load(kTwoLink);
  CHECK(m.experiment.task.path == HandTask::Path::none);
  CHECK(m.experiment.controller.kind == ControllerSpec::Kind::open_loop);
  CHECK(approx(m.experiment.controller.kp, Eigen::Vector2d(50, 50)));  // expanded to one per joint
  CHECK(approx(m.experiment.controller.kd, Eigen::Vector2d(2, 2)));
  CHECK(m.experiment.controller.desired_force == 5.0);
  CHECK(m.model.hand_load.mass == 0.0);
  CHECK(approx(m.model.hand_load.force, Eigen::Vector3d::Zero()));
}

TEST_CASE("task: a line from the start pose, kept elbow, posture, limits, pd_feedforward") {
  const Scenario m = load(three_link_with(R"(
initial: {q: [0.1, 0.2, 0.1]}
task:
  path: line
  timing: minimum_jerk
  start_delay: 0.5
  duration: 2.0
  points: [start, [0.45, 0, 0.05]]
  elbows: [elbow]
  elbow_clearance: 0.02
  posture_weight: 0.1
  joint_limits: {min: [-1, -2, -2], max: [1, 2, 2]}
controller: {type: pd_feedforward, kp: [40, 30, 20], kd: 1.5}
hand_load: {mass: 0.2, force: [0, 0, -1]}
)"));
  const HandTask& t = m.experiment.task;
  CHECK(t.path == HandTask::Path::line);
  CHECK(t.timing == HandTask::Timing::minimum_jerk);
  CHECK(t.start_delay == 0.5);
  CHECK(t.duration == 2.0);
  REQUIRE(t.points.size() == 2);
  CHECK(t.points[0].array().isNaN().all());  // `start`: the engine puts the initial hand there
  CHECK(approx(t.points[1], Eigen::Vector3d(0.45, 0, 0.05)));
  REQUIRE(t.elbows.size() == 1);
  CHECK(t.elbows[0] == "elbow");
  CHECK(t.elbow_clearance == 0.02);
  CHECK(approx(t.posture, Eigen::Vector3d(0.1, 0.2, 0.1)));  // default: initial q
  CHECK(t.posture_weight == 0.1);
  CHECK(approx(t.q_min, Eigen::Vector3d(-1, -2, -2)));
  CHECK(approx(t.q_max, Eigen::Vector3d(1, 2, 2)));
  CHECK(m.experiment.controller.kind == ControllerSpec::Kind::pd_feedforward);
  CHECK(approx(m.experiment.controller.kp, Eigen::Vector3d(40, 30, 20)));
  CHECK(approx(m.experiment.controller.kd, Eigen::Vector3d(1.5, 1.5, 1.5)));
  CHECK(m.model.hand_load.mass == 0.2);
  CHECK(approx(m.model.hand_load.force, Eigen::Vector3d(0, 0, -1)));
}

TEST_CASE("task: circle, waypoints, hold; force control") {
  const Scenario c = load(three_link_with(R"(
task: {path: circle, center: [0.4, 0, 0.1], radius: 0.03, normal: [0, 2, 0], start_angle: 1.0,
       elbows: [elbow], posture: [0.3, -0.3, 0.2]}
controller: {type: force, desired_force: 8}
)"));
  CHECK(c.experiment.task.path == HandTask::Path::circle);
  CHECK(c.experiment.task.points.empty());
  CHECK(approx(c.experiment.task.center, Eigen::Vector3d(0.4, 0, 0.1)));
  CHECK(c.experiment.task.radius == 0.03);
  CHECK(approx(c.experiment.task.normal, Eigen::Vector3d(0, 1, 0)));  // normalized
  CHECK(c.experiment.task.start_angle == 1.0);
  CHECK(approx(c.experiment.task.posture, Eigen::Vector3d(0.3, -0.3, 0.2)));
  CHECK(c.experiment.controller.kind == ControllerSpec::Kind::force);
  CHECK(c.experiment.controller.desired_force == 8.0);

  const Scenario w = load(two_link_with("task: {path: waypoints, points: [[0.4, 0, 0], [0.4, 0, 0.1], "
                                     "[0.3, 0, 0.1]]}\n"));
  CHECK(w.experiment.task.points.size() == 3);
  CHECK(w.experiment.task.q_min.size() == 0);  // no limits

  const Scenario h = load(two_link_with("task: {path: hold}\ncontroller: {type: pd}\n"));
  CHECK(h.experiment.task.path == HandTask::Path::hold);
  CHECK(h.experiment.task.points.empty());  // hold the start
  CHECK(h.experiment.controller.kind == ControllerSpec::Kind::pd);
}

TEST_CASE("task: elbow kept above the table with contact on; keys set from the command line") {
  const Scenario m =
      load(three_link_with("task: {path: hold, elbows: [elbow], elbow_clearance: 0.05}\n"));
  CHECK(m.model.effects.contact);
  CHECK(m.experiment.task.elbow_clearance == 0.05);
  const Scenario o = load(scene_with("task: {path: hold}\n"),
                       {"task.duration=3", "controller.type=pd", "controller.kp=7"});
  CHECK(o.experiment.task.duration == 3.0);
  CHECK(approx(o.experiment.controller.kp, Eigen::Vector2d(7, 7)));
}

// ---------------------------------------------------------------------------
// Errors: each names line, column and key path.

TEST_CASE("task error: keys, path and timing") {
  CHECK_ERROR(two_link_with("task:\n  path: line\n  pionts: []\n"), "x.yaml:11:3:", "task.pionts",
              "unknown key \"pionts\" (did you mean \"points\"?)");
  CHECK_ERROR(two_link_with("task:\n  duration: 1\n"), "x.yaml:10:3:", "task.path",
              "required key is missing");
  CHECK_ERROR(two_link_with("task: {path: spiral}\n"), "x.yaml:9:14:", "task.path",
              "must be one of hold, line, circle, waypoints");
  CHECK_ERROR(two_link_with("task: {path: hold, timing: cubic}\n"), "x.yaml:9:28:", "task.timing",
              "must be one of quintic, minimum_jerk");
  CHECK_ERROR(two_link_with("task: {path: hold, duration: 0}\n"), "x.yaml:9:30:", "task.duration",
              "must be > 0 (got 0)");
  CHECK_ERROR(two_link_with("task: {path: hold, start_delay: -1}\n"),
              "x.yaml:9:33:", "task.start_delay", "must be >= 0");
}

TEST_CASE("task error: points by path") {
  CHECK_ERROR(two_link_with("task:\n  path: line\n  points: [[0, 0, 0]]\n"),
              "x.yaml:11:11:", "task.points", "a line needs exactly 2 points (got 1)");
  CHECK_ERROR(two_link_with("task: {path: waypoints, points: [start]}\n"),
              "x.yaml:9:33:", "task.points", "waypoints need at least 2 points (got 1)");
  CHECK_ERROR(two_link_with("task: {path: hold, points: [start, start]}\n"),
              "x.yaml:9:36:", "task.points[1]", "only the first point may be `start`");
  CHECK_ERROR(two_link_with("task: {path: line, points: [start, [1, 2]]}\n"),
              "x.yaml:9:36:", "task.points[1]", "expected a list of 3 numbers");
  CHECK_ERROR(two_link_with("task: {path: line}\n"), "x.yaml:9:7:", "task.points",
              "required key is missing");
}

TEST_CASE("task error: circle keys") {
  CHECK_ERROR(two_link_with("task: {path: line, points: [start, start], radius: 0.1}\n"),
              "x.yaml:9:", "task.radius", "is only for path: circle (this path is line)");
  CHECK_ERROR(two_link_with("task: {path: circle, center: [0, 0, 0], radius: 1, points: []}\n"),
              "x.yaml:9:", "task.points", "is not used by path: circle");
  CHECK_ERROR(two_link_with("task: {path: circle, center: [0, 0, 0], radius: 0}\n"),
              "x.yaml:9:", "task.radius", "must be > 0");
  CHECK_ERROR(two_link_with("task: {path: circle, radius: 0.1}\n"), "x.yaml:9:7:", "task.center",
              "required key is missing");
  CHECK_ERROR(
      two_link_with("task: {path: circle, center: [0, 0, 0], radius: 1, normal: [0, 0, 0]}\n"),
      "x.yaml:9:", "task.normal", "must be non-zero");
}

TEST_CASE("task error: elbows, clearance, posture, joint limits") {
  CHECK_ERROR(scene_with("task:\n  path: hold\n  elbows: [wrist]\n"),
              "x.yaml:14:12:", "task.elbows[0]", "no elbow named \"wrist\" in elbows: elbow");
  CHECK_ERROR(scene_with("task: {path: hold, elbows: [elbow, elbow]}\n"),
              "x.yaml:12:", "task.elbows[1]", "is listed twice");
  CHECK_ERROR(two_link_with("elbows: [{link: 0, at: 0.1}]\ntask: {path: hold, elbows: [elbow0]}\n"),
              "x.yaml:10:", "task.elbows", "needs a table");
  CHECK_ERROR(scene_with("task: {path: hold, elbow_clearance: -0.01}\n"),
              "x.yaml:12:", "task.elbow_clearance", "must be >= 0");
  CHECK_ERROR(two_link_with("task: {path: hold, posture: [0, 0, 0]}\n"),
              "x.yaml:9:", "task.posture", "expected a list of 2 numbers (one per joint) (got 3)");
  CHECK_ERROR(two_link_with("task: {path: hold, posture_weight: 0}\n"),
              "x.yaml:9:", "task.posture_weight", "must be > 0");
  CHECK_ERROR(two_link_with(R"(
task:
  path: hold
  joint_limits:
    min: [-1, 1]
    max: [1, 1]
)"),
              "x.yaml:13:14:", "task.joint_limits.max[1]", "must be > min[1] (min 1, max 1)");
  CHECK_ERROR(two_link_with("task: {path: hold, joint_limits: {min: [0, 0]}}\n"),
              "x.yaml:9:", "task.joint_limits.max", "required key is missing");
}

TEST_CASE("controller error: what a closed loop needs") {
  CHECK_ERROR(two_link_with("controller:\n  type: pd\n"), "x.yaml:10:9:", "controller.type",
              "controller pd needs a task");
  CHECK_ERROR(two_link_with("effects: {motor: none}\ntask: {path: hold}\ncontroller: {type: pd}\n"),
              "x.yaml:11:", "controller.type", "needs effects.motor quasi_static or full");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: force}\n"),
              "x.yaml:13:", "controller.type", "needs task.elbows");
  CHECK_ERROR(two_link_with(R"(
elbows: [{name: elbow, link: 0, at: 0.3}]
table: {boxes: [{center: [0.4, 0, -0.2], size: [1.0, 0.6, 0.1]}]}
task: {path: hold, elbows: [elbow]}
controller: {type: force}
)"),
              "x.yaml:12:", "controller.type", "needs effects.contact: true");
  CHECK_ERROR(two_link_with("controller: {type: pid}\n"), "x.yaml:9:", "controller.type",
              "must be one of open_loop, pd, pd_feedforward, force");
}

TEST_CASE("controller and hand_load error: values") {
  CHECK_ERROR(two_link_with("controller:\n  kp: [1, -2]\n"), "x.yaml:10:", "controller.kp[1]",
              "must be >= 0 (got -2)");
  CHECK_ERROR(two_link_with("controller: {kd: [1, 2, 3]}\n"), "x.yaml:9:", "controller.kd",
              "one per joint");
  CHECK_ERROR(two_link_with("controller: {kd: -1}\n"), "x.yaml:9:", "controller.kd",
              "must be >= 0");
  CHECK_ERROR(two_link_with("controller: {desired_force: 0}\n"),
              "x.yaml:9:", "controller.desired_force", "must be > 0");
  CHECK_ERROR(two_link_with("controller: {type: pd, gain: 1}\n"), "x.yaml:9:", "controller.gain",
              "unknown key");
  CHECK_ERROR(two_link_with("hand_load:\n  mass: -1\n"), "x.yaml:10:9:", "hand_load.mass",
              "must be >= 0 (got -1)");
  CHECK_ERROR(two_link_with("hand_load: {force: [0, 1]}\n"), "x.yaml:9:", "hand_load.force",
              "expected a list of 3 numbers");
}

// ---------------------------------------------------------------------------
// controller.model: what the controller believes, where it differs from the plant

TEST_CASE("controller.model: a second model with the believed values; the plant unchanged") {
  const Scenario plain = load(scene_with("task: {path: hold}\ncontroller: {type: pd_feedforward}\n"));
  CHECK(plain.experiment.controller_model == nullptr);
  CHECK(&plain.experiment.believed(plain.model) == &plain.model);
  CHECK(plain.controller_model_overrides.empty());

  const Scenario m = load(scene_with(R"(
task: {path: hold}
hand_load: {mass: 0.2}
controller:
  type: pd_feedforward
  model:
    robot.planar.links[0].mass: 1.1
    hand_load.mass: 0
    motors.default.resistance: 2.5
)"));
  REQUIRE(m.experiment.controller_model != nullptr);
  const Model& believed = *m.experiment.controller_model;
  CHECK(&m.experiment.believed(m.model) == &believed);
  CHECK(m.model.links[0].mass == 1.0);
  CHECK(believed.links[0].mass == 1.1);
  CHECK(m.model.hand_load.mass == 0.2);
  CHECK(believed.hand_load.mass == 0.0);
  CHECK(believed.resistance[0] == 2.5);
  CHECK(m.model.resistance[0] != 2.5);
  // The payload rides on the hand's link: the plant carries it, the controller does not know.
  CHECK(m.model.links[1].mass == doctest::Approx(0.5 + 0.2));
  CHECK(believed.links[1].mass == doctest::Approx(0.5));
  CHECK(believed.links[1].tip == m.model.links[1].tip);  // the rest as the plant's
  CHECK(m.controller_model_overrides ==
        std::vector<std::string>{"robot.planar.links[0].mass=1.1", "hand_load.mass=0",
                                 "motors.default.resistance=2.5"});
}

TEST_CASE("controller.model error: keys the plan does not read, structure, values") {
  CHECK_ERROR(scene_with("controller:\n  model:\n    simulation.step: 1e-4\n"), "x.yaml:14:5:",
              "controller.model.simulation.step", "may change robot, motors, gravity");
  CHECK_ERROR(scene_with("controller:\n  model:\n    effects.contact: false\n"), "x.yaml:14:",
              "controller.model.effects.contact", "may change robot");
  CHECK_ERROR(scene_with("controller:\n  model: [1, 2]\n"), "x.yaml:13:", "controller.model",
              "expected a map of key.path: value");
  CHECK_ERROR(scene_with("controller:\n  model:\n    robot.planar.links[0].mass: -1\n"),
              "x.yaml:14:5:", "robot.planar.links[0].mass", "in the controller's model");
  CHECK_ERROR(scene_with("controller:\n  model:\n    robot.planar.links[5].mass: 2\n"),
              "x.yaml:14:5:", "robot.planar.links[5]", "index out of range");
  CHECK_ERROR(scene_with("controller:\n  model:\n    robot.planar.links: [{length: 0.3, mass: 1}]\n"),
              "x.yaml:14:5:", "controller.model", "the plant's number of joints (2), got 1");
}

// ---------------------------------------------------------------------------
// controller: the digital loop (sample_rate, delay, pwm_bits, sensors)

TEST_CASE("controller: a digital loop at 1 kHz with an encoder, noise and a velocity filter") {
  const Scenario plain = load(scene_with("task: {path: hold}\ncontroller: {type: pd}\n"));
  CHECK_FALSE(plain.experiment.controller.loop.sampled());  // default: continuous
  const Scenario m = load(scene_with(R"(
task: {path: hold}
controller:
  type: pd
  sample_rate: 1000
  delay: 1
  pwm_bits: 12
  sensors:
    encoder: {counts_per_rev: 4096, side: joint}
    noise: 1.0e-5
    velocity_cutoff: 200
    seed: 42
)"));
  const elbowsim::DigitalLoopSpec& loop = m.experiment.controller.loop;
  CHECK(loop.sampled());
  CHECK(loop.sample_period == doctest::Approx(1e-3));
  CHECK(loop.delay == 1);
  CHECK(loop.pwm_bits == 12);
  CHECK(loop.sensors.counts_per_rev == 4096);
  CHECK(loop.sensors.side == elbowsim::SensorSpec::EncoderSide::joint);
  CHECK(loop.sensors.noise == 1e-5);
  CHECK(loop.sensors.velocity_cutoff == 200);
  CHECK(loop.sensors.seed == 42);
}

TEST_CASE("controller error: the digital loop") {
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, delay: 1}\n"), "x.yaml:13:",
              "controller.delay", "needs controller.sample_rate");
  CHECK_ERROR(scene_with("controller: {sample_rate: 1000}\n"), "x.yaml:12:",
              "controller.sample_rate", "an open-loop scene has no control loop");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, sample_rate: 5000}\n"),
              "x.yaml:13:", "controller.sample_rate", "shorter than simulation.step");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, sample_rate: -1}\n"),
              "x.yaml:13:", "controller.sample_rate", "must be > 0");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, sample_rate: 100, delay: 1.5}\n"),
              "x.yaml:13:", "controller.delay", "whole number");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, sample_rate: 100, pwm_bits: 0}\n"),
              "x.yaml:13:", "controller.pwm_bits", "from 1 to 32");
  CHECK_ERROR(scene_with(R"(
task: {path: hold}
controller: {type: pd, sample_rate: 100, sensors: {encoder: {side: joint}}}
)"),
              "x.yaml:13:", "controller.sensors.encoder.counts_per_rev", "required key is missing");
  CHECK_ERROR(scene_with(R"(
task: {path: hold}
controller: {type: pd, sample_rate: 100, sensors: {encoder: {counts_per_rev: 10, side: wheel}}}
)"),
              "x.yaml:13:", "controller.sensors.encoder.side", "must be one of motor, joint");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, sample_rate: 100, sensors: {noise: -1}}\n"),
              "x.yaml:13:", "controller.sensors.noise", "must be >= 0");
}

// ---------------------------------------------------------------------------
// controller.tuning and ki (engine/control/tuning.hpp)

TEST_CASE("controller: a tuning rule and hand-given integral gains") {
  const Scenario tuned = load(scene_with(
      "task: {path: hold}\ncontroller: {type: pd, sample_rate: 1000, tuning: {bandwidth: 10, "
      "damping: 0.7, integral: 0.5}}\n"));
  const elbowsim::TuningRule& rule = tuned.experiment.controller.tuning;
  CHECK(rule.given());
  CHECK(rule.bandwidth == 10);
  CHECK(rule.damping == 0.7);
  CHECK(rule.integral == 0.5);
  const Scenario defaults =
      load(scene_with("task: {path: hold}\ncontroller: {type: pd, tuning: {bandwidth: 5}}\n"));
  CHECK(defaults.experiment.controller.tuning.damping == 1.0);  // critically damped, PD
  CHECK(defaults.experiment.controller.tuning.integral == 0.0);
  CHECK_FALSE(defaults.experiment.controller.integral());
  const Scenario given = load(scene_with(
      "task: {path: hold}\ncontroller: {type: pd, sample_rate: 1000, ki: [3, 4]}\n"));
  CHECK_FALSE(given.experiment.controller.tuning.given());
  CHECK(given.experiment.controller.integral());
  CHECK(given.experiment.controller.ki == Eigen::Vector2d(3, 4));
}

TEST_CASE("the experiment's controllers: each arm tuned by the rule; no integral on the joints the resting elbow holds") {
  const std::string file = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  const Scenario on = elbowsim::load_scenario_variant(file, "elbow_on");
  const Scenario off = elbowsim::load_scenario_variant(file, "elbow_off");
  const auto resting = elbowsim::make_controller(on.model, on.experiment);
  const auto held_up = elbowsim::make_controller(off.model, off.experiment);
  CHECK(resting->integral_held == std::vector<int>{0, 1});
  CHECK(resting->spec.ki[0] == 0);
  CHECK(resting->spec.ki[1] == 0);
  CHECK(resting->spec.ki[2] > 0);
  CHECK(held_up->integral_held.empty());
  CHECK((held_up->spec.ki.array() > 0).all());
  // Each arm's gains from its own inertia: the held-up arm's shoulder is
  // heavier at its start pose, so its Kp is larger.
  CHECK(held_up->spec.kp[0] > resting->spec.kp[0]);
  CHECK(resting->tuning_inertia.size() == 4);
}

TEST_CASE("controller error: tuning and ki") {
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, kp: 5, tuning: {bandwidth: 10}}\n"),
              "x.yaml:13:", "controller.tuning", "give the rule or the gains (controller.kp)");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, tuning: {damping: 1}}\n"),
              "x.yaml:13:", "controller.tuning.bandwidth", "required key is missing");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, tuning: {bandwidth: 10, zeta: 1}}\n"),
              "x.yaml:13:", "controller.tuning.zeta", "unknown key");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, tuning: {bandwidth: 10, integral: 0.5}}\n"),
              "x.yaml:13:", "controller.tuning.integral", "needs controller.sample_rate");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, ki: 2}\n"), "x.yaml:13:",
              "controller.ki", "needs controller.sample_rate");
  CHECK_ERROR(scene_with("controller: {tuning: {bandwidth: 10}}\n"), "x.yaml:12:",
              "controller.tuning", "an open-loop scene has no gains to tune");
  CHECK_ERROR(scene_with("task: {path: hold}\ncontroller: {type: pd, tuning: {bandwidth: 0}}\n"),
              "x.yaml:13:", "controller.tuning.bandwidth", "must be > 0");
}

TEST_CASE("controller.model: a table believed where the initial pose would be inside it loads (the plant's is checked)") {
  // The arm lies along z = 0 at q = 0 with no elbow sphere radius given:
  // a table believed with its top at z = 0.01 would hold the elbow 1 cm deep.
  const Scenario s = load(scene_with(R"(
controller:
  model:
    table.boxes[0].center: [0.4, 0, -0.04]
)"));
  REQUIRE(s.experiment.controller_model);
  CHECK(s.experiment.controller_model->table[0].center.z() == -0.04);
  CHECK(s.model.table[0].center.z() == -0.2);
  // The plant's own table there is an error, as before.
  CHECK_ERROR(two_link_with(R"(
effects: {contact: true}
elbows: [{name: elbow, link: 0, at: 0.3}]
table: {boxes: [{center: [0.4, 0, -0.04], size: [1.0, 0.6, 0.1]}]}
)"),
              "x.yaml:", "elbows[0]", "inside table box 0 at the initial pose");
}

TEST_CASE("simulation: optional with a task (its timing gives the duration; 1 ms, rk4, crba)") {
  const Scenario s = load_scenario_text(yaml(R"(
name: two_link
robot:
  planar:
    links: [{length: 0.3, mass: 1}, {length: 0.2, mass: 0.5}]
task: {path: hold, start_delay: 0.2, duration: 0.5}
controller: {type: pd}
)"), "x.yaml");
  CHECK(s.model.options.duration == doctest::Approx(0.2 + 0.5 + 0.5));
  CHECK(s.model.options.step == 1e-3);
  CHECK(s.model.options.integrator == elbowsim::IntegratorKind::rk4);
}

// The shipped experiment's plan: waypoints through a C2 spline and a C2 time
// scaling give joint accelerations without jumps, so the feed-forward
// currents and torques have no kinks. Between samples 1 ms apart a continuous
// q̈ changes by jerk x 1 ms: at most 0.20 rad/s^2 here (the jerk of the tight
// turn at each loop's top, about 200 rad/s^3). The C1 Catmull-Rom spline the
// paths used before jumps at every point: by 11.3 rad/s^2 (elbow on) and 5.4
// (off) on these loops (measured), so the bound 1 rad/s^2 fails there.
TEST_CASE("the experiment's plan has continuous joint accelerations (q̈ changes by < 1 rad/s^2 per 1 ms sample)") {
  const std::string file = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/elbow_experiment.yaml";
  for (const char* variant : {"elbow_on", "elbow_off"}) {
    CAPTURE(variant);
    // The plan is sampled on the step; the bound and the measured jumps are per 1 ms.
    const Scenario s = elbowsim::load_scenario_variant(file, variant, {"simulation.step=1e-3"});
    const auto plan = elbowsim::make_plan(s.model, s.experiment);
    REQUIRE(plan->qdd.size() > 100);
    REQUIRE(plan->dt == doctest::Approx(1e-3));
    double largest = 0;
    for (std::size_t k = 0; k + 1 < plan->qdd.size(); ++k)
      largest = std::max(largest, (plan->qdd[k + 1] - plan->qdd[k]).cwiseAbs().maxCoeff());
    CHECK(largest < 1.0);
  }
}

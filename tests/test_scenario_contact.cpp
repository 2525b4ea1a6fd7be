// Scenario loader: elbows, table and contact settings (effects.contact,
// friction, impacts, stabilization; elbows; table.boxes; contact options), the
// Model members they fill, and their errors. Fixtures and CHECK_ERROR are in
// test_scenario_helpers.hpp; kTwoLink has 8 lines, so sections appended with
// two_link_with() start at line 9.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "app/scenario/scenario.hpp"
#include "test_scenario_helpers.hpp"

using elbowsim::ContactOptions;
using elbowsim::EventTiming;
using elbowsim::FrictionLaw;
using elbowsim::load_scenario;
using elbowsim::Model;
using elbowsim::Scenario;
using elbowsim::Stabilization;
using namespace scenario_test;

namespace {

// A table that fits any of the fixtures below.
// The arm lies along x at z = 0 (q = 0): the table top is 0.15 m below it.
const char* kTable = "table: {boxes: [{center: [0.4, 0, -0.2], size: [1.0, 0.6, 0.1]}]}\n";

// Two joints in the general form (no `at` allowed); link 0 ends at x = 0.3.
const std::string kGeneral = yaml(R"(
name: general
robot:
  joints:
    - link: {mass: 1, inertia: {ixx: 0.01, iyy: 0.01, izz: 0.01}, tip: [0.3, 0, 0]}
    - origin: {xyz: [0.3, 0, 0]}
      link: {mass: 1, inertia: {ixx: 0.01, iyy: 0.01, izz: 0.01}}
simulation: {duration: 1}
)");

}  // namespace

// ---------------------------------------------------------------------------
// Valid scenes

TEST_CASE("contact: defaults without the new sections") {
  const Model m = load(kTwoLink).model;
  CHECK_FALSE(m.effects.contact);
  CHECK_FALSE(m.effects.friction);
  CHECK(m.effects.impacts);
  CHECK(m.effects.stabilization == Stabilization::baumgarte);
  CHECK(m.elbows.empty());
  CHECK(m.table.empty());
  const ContactOptions d;
  CHECK(m.contact.restitution == d.restitution);
  CHECK(m.contact.friction.law == FrictionLaw::coulomb);
  CHECK(m.contact.friction.mu == d.friction.mu);
  CHECK(m.contact.friction.stick_velocity == d.friction.stick_velocity);
  CHECK(m.contact.events == d.events);
  CHECK(m.contact.locate_tolerance == d.locate_tolerance);
  CHECK(m.contact.touch_distance == d.touch_distance);
  CHECK(m.contact.separation_velocity == d.separation_velocity);
  CHECK(m.contact.baumgarte_time == d.baumgarte_time);
  CHECK(m.contact.rank_tolerance == d.rank_tolerance);
  CHECK(m.contact.initial_penetration == d.initial_penetration);
}

TEST_CASE("contact: a planar scene with two elbows and a two-box table") {
  Scenario s = load(two_link_with(R"(
effects: {contact: true, friction: true, impacts: false, stabilization: projection}
elbows:
  - {name: left, link: 0, at: 0.3, radius: 0.04}
  - {link: -1, at: 0.1}
table:
  boxes:
    - {center: [0.4, 0, -0.2], size: [1.0, 0.6, 0.1]}
    - {center: [0.9, 0.1, -0.5], size: [0.2, 0.3, 0.4], rpy: [0.1, 0.2, 0.3]}
contact:
  restitution: 0.5
  friction: {law: saturated, mu: 0.3, slip_velocity: 5e-4, stick_velocity: 2e-6, tanh_velocity: 3e-3}
  events: locate
  locate_tolerance: 1e-8
  touch_distance: 2e-6
  separation_velocity: 3e-6
  baumgarte_time: 0.02
  rank_tolerance: 1e-6
  initial_penetration: 2e-4
  penetration_tolerance: 2e-3
  detection_margin: 0.02
  max_rows: 7
validity: {energy_residual: 1e-4, current_factor: 5, speed_factor: 4, rest_share: 0.8}
)"));
  const Model& m = s.model;
  CHECK(m.effects.contact);
  CHECK(m.effects.friction);
  CHECK_FALSE(m.effects.impacts);
  CHECK(m.effects.stabilization == Stabilization::projection);

  // Elbows: `at` is the point (at, 0, 0); -1 is the last link; default name elbow<k>.
  REQUIRE(m.elbows.size() == 2);
  CHECK(m.elbows[0].name == "left");
  CHECK(m.elbows[0].link == 0);
  CHECK(approx(m.elbows[0].point, Eigen::Vector3d(0.3, 0, 0)));
  CHECK(m.elbows[0].radius == doctest::Approx(0.04));
  CHECK(m.elbows[1].name == "elbow1");
  CHECK(m.elbows[1].link == 1);
  CHECK(approx(m.elbows[1].point, Eigen::Vector3d(0.1, 0, 0)));
  CHECK(m.elbows[1].radius == doctest::Approx(0.03));  // the loader's default

  // Table: rotation R = Rz(yaw) Ry(pitch) Rx(roll), as for robot.base.
  REQUIRE(m.table.size() == 2);
  CHECK(approx(m.table[0].center, Eigen::Vector3d(0.4, 0, -0.2)));
  CHECK(approx(m.table[0].size, Eigen::Vector3d(1.0, 0.6, 0.1)));
  CHECK(approx(m.table[0].rotation, Eigen::Matrix3d::Identity()));
  CHECK(approx(m.table[1].center, Eigen::Vector3d(0.9, 0.1, -0.5)));
  CHECK(approx(m.table[1].size, Eigen::Vector3d(0.2, 0.3, 0.4)));
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  CHECK(approx(m.table[1].rotation, r));

  // Options: every key given.
  CHECK(m.contact.restitution == doctest::Approx(0.5));
  CHECK(m.contact.friction.law == FrictionLaw::saturated);
  CHECK(m.contact.friction.mu == doctest::Approx(0.3));
  CHECK(m.contact.friction.slip_velocity == doctest::Approx(5e-4));
  CHECK(m.contact.friction.stick_velocity == doctest::Approx(2e-6));
  CHECK(m.contact.friction.tanh_velocity == doctest::Approx(3e-3));
  CHECK(m.contact.events == EventTiming::locate);
  CHECK(m.contact.locate_tolerance == doctest::Approx(1e-8));
  CHECK(m.contact.touch_distance == doctest::Approx(2e-6));
  CHECK(m.contact.separation_velocity == doctest::Approx(3e-6));
  CHECK(m.contact.baumgarte_time == doctest::Approx(0.02));
  CHECK(m.contact.rank_tolerance == doctest::Approx(1e-6));
  CHECK(m.contact.initial_penetration == doctest::Approx(2e-4));
  CHECK(m.contact.penetration_tolerance == doctest::Approx(2e-3));
  CHECK(m.contact.detection_margin == doctest::Approx(0.02));
  CHECK(m.contact.max_rows == 7);
  CHECK(m.validity.energy_residual == doctest::Approx(1e-4));
  CHECK(m.validity.current_factor == doctest::Approx(5));
  CHECK(m.validity.speed_factor == doctest::Approx(4));
  CHECK(m.validity.rest_share == doctest::Approx(0.8));
}

TEST_CASE("contact: general robots give point; at may sit at either end of the link") {
  Scenario s = load(kGeneral + yaml(R"(
effects: {contact: true}
elbows:
  - {name: a, link: 1, point: [0.05, 0.01, -0.02], radius: 0.01}
)") + kTable);
  REQUIRE(s.model.elbows.size() == 1);
  CHECK(s.model.elbows[0].link == 1);
  CHECK(approx(s.model.elbows[0].point, Eigen::Vector3d(0.05, 0.01, -0.02)));

  // Planar robots take point too; at = 0 and at = length are on the link.
  Scenario p = load(two_link_with(R"(
elbows:
  - {link: 0, at: 0}
  - {link: 1, at: 0.2}
  - {link: 1, point: [0.1, 0, 0.01]}
)"));
  REQUIRE(p.model.elbows.size() == 3);
  CHECK(approx(p.model.elbows[1].point, Eigen::Vector3d(0.2, 0, 0)));
  CHECK(approx(p.model.elbows[2].point, Eigen::Vector3d(0.1, 0, 0.01)));
}

TEST_CASE("contact: elbows and table are validated, then kept, with contact off") {
  Scenario s = load(two_link_with("elbows: [{link: 0, at: 0.1}]\n") + kTable);
  CHECK_FALSE(s.model.effects.contact);
  CHECK(s.model.elbows.size() == 1);
  CHECK(s.model.table.size() == 1);
  CHECK(load(two_link_with("elbows: []\n")).model.elbows.empty());  // any number, with contact off
  CHECK_ERROR(two_link_with("elbows: [{link: 0, at: 0.1, radius: -1}]\n"),
              "x.yaml:9:", "elbows[0].radius", "must be > 0 (got -1)");
}

TEST_CASE("contact: switched on from the command line") {
  const std::string scene = two_link_with("elbows: [{link: 0, at: 0.3}]\n") + kTable;
  CHECK(load(scene, {"effects.contact=true"}).model.effects.contact);
  CHECK(load(scene, {"effects.contact=true", "elbows[0].at=0.2"}).model.elbows[0].point.x() ==
        doctest::Approx(0.2));
  CHECK(error_of(kTwoLink, {"effects.contact=true"})
            .starts_with("command line --set effects.contact=true: effects.contact: needs a table"));
}

// ---------------------------------------------------------------------------
// Errors: each names line, column and key path.

TEST_CASE("contact error: elbow radius must be positive") {
  CHECK_ERROR(two_link_with(R"(
elbows:
  - link: 0
    at: 0.1
    radius: 0
)"),
              "x.yaml:12:13:", "elbows[0].radius", "must be > 0 (got 0)");
}

TEST_CASE("contact error: elbow link index out of range") {
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 2, at: 0.1}\n"), "x.yaml:10:12:", "elbows[0].link",
              "link index out of range (got 2; the robot has 2 links: -2 .. 1)");
  CHECK_ERROR(two_link_with("elbows:\n  - {link: -3, at: 0.1}\n"),
              "x.yaml:10:12:", "elbows[0].link", "out of range (got -3");
  CHECK_ERROR(two_link_with("elbows:\n  - {at: 0.1}\n"), "x.yaml:10:5:", "elbows[0].link",
              "required key is missing");
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 0.5, at: 0.1}\n"),
              "x.yaml:10:12:", "elbows[0].link", "expected a whole number");
}

TEST_CASE("contact error: at is for planar robots, and must lie on the link") {
  CHECK_ERROR(kGeneral + yaml(R"(
elbows:
  - {link: 1, point: [0.05, 0, 0]}
  - {link: 0, at: 0.2}
)"),
              "x.yaml:10:19:", "elbows[1].at", "is only for the planar shorthand");
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 1, at: 0.25}\n"), "x.yaml:10:19:", "elbows[0].at",
              "must be <= the length of link 1 (0.2 m; got 0.25)");
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 0, at: -0.1}\n"), "x.yaml:10:19:", "elbows[0].at",
              "must be >= 0 (got -0.1)");
}

TEST_CASE("contact error: exactly one of at and point") {
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 0, at: 0.1, point: [0.1, 0, 0]}\n"),
              "x.yaml:10:5:", "elbows[0]", "give exactly one of at or point (got both)");
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 0}\n"), "x.yaml:10:5:", "elbows[0]",
              "give exactly one of at (distance along the link [m]) or point");
  CHECK_ERROR(kGeneral + yaml("elbows:\n  - {link: 0, radius: 0.02}\n"), "x.yaml:9:5:", "elbows[0]",
              "missing the sphere centre: give point");
}

TEST_CASE("contact error: elbow names are unique") {
  CHECK_ERROR(two_link_with(R"(
elbows:
  - {name: tip, link: 1, at: 0.2}
  - {name: left, link: 0, at: 0.3}
  - {name: tip, link: 0, at: 0.1}
)"),
              "x.yaml:12:12:", "elbows[2].name", "duplicate elbow name \"tip\" (also elbows[0])");
  // A default name (elbow<k>) taken by an explicit one.
  CHECK_ERROR(two_link_with(R"(
elbows:
  - {name: elbow1, link: 0, at: 0.3}
  - {link: 1, at: 0.1}
)"),
              "x.yaml:11:5:", "elbows[1]",
              "the default name \"elbow1\" is taken by elbows[0]; give this elbow a name");
  CHECK_ERROR(two_link_with("elbows:\n  - {name: \"\", link: 0, at: 0.1}\n"),
              "x.yaml:10:", "elbows[0].name", "must not be empty");
}

TEST_CASE("contact error: friction needs contact") {
  CHECK_ERROR(two_link_with("effects: {friction: true}\n"), "x.yaml:9:21:", "effects.friction",
              "needs effects.contact: true");
  CHECK_ERROR(two_link_with("effects:\n  contact: false\n  friction: true\n"),
              "x.yaml:11:13:", "effects.friction", "needs effects.contact: true");
}

TEST_CASE("contact: the links touch the table without declared elbows; contact needs a table") {
  // Every link's solid touches the table, so elbows are optional.
  const Scenario no_elbows = elbowsim::load_scenario_text(two_link_with("effects: {contact: true}\n") + kTable, "x.yaml");
  CHECK(no_elbows.model.effects.contact);
  CHECK(no_elbows.model.elbows.empty());
  CHECK_ERROR(two_link_with("effects: {contact: true}\nelbows: [{link: 0, at: 0.1}]\n"),
              "x.yaml:9:20:", "effects.contact", "needs a table");
  CHECK_ERROR(two_link_with("table: {boxes: []}\n"), "x.yaml:9:16:", "table.boxes",
              "needs at least one box");
  CHECK_ERROR(two_link_with("table: {}\n"), "x.yaml:9:8:", "table.boxes",
              "required key is missing");
}

TEST_CASE("contact error: table boxes") {
  CHECK_ERROR(two_link_with(R"(
table:
  boxes:
    - center: [0, 0, 0]
      size: [1, 0.5, 0]
)"),
              "x.yaml:12:22:", "table.boxes[0].size[2]", "must be > 0 (got 0)");
  CHECK_ERROR(two_link_with("table:\n  boxes:\n    - {center: [0, 0, 0], size: [1, -1, 1]}\n"),
              "x.yaml:11:37:", "table.boxes[0].size[1]", "must be > 0 (got -1)");
  CHECK_ERROR(two_link_with("table:\n  boxes:\n    - {center: [0, 0, 0], size: [1, 1]}\n"),
              "x.yaml:11:33:", "table.boxes[0].size", "expected a list of 3 numbers");
  CHECK_ERROR(two_link_with("table:\n  boxes:\n    - {size: [1, 1, 1]}\n"),
              "x.yaml:11:7:", "table.boxes[0].center", "required key is missing");
}

TEST_CASE("contact error: contact options out of range") {
  CHECK_ERROR(two_link_with("contact:\n  restitution: 1.5\n"),
              "x.yaml:10:16:", "contact.restitution", "must be in [0, 1] (got 1.5)");
  CHECK_ERROR(two_link_with("contact:\n  restitution: -0.1\n"),
              "x.yaml:10:16:", "contact.restitution", "must be in [0, 1] (got -0.1)");
  CHECK(error_of(two_link_with("contact: {restitution: 1}\n")).empty());
  CHECK_ERROR(two_link_with("contact:\n  friction: -0.2\n"), "x.yaml:10:13:", "contact.friction",
              "must be >= 0 (got -0.2)");
  CHECK_ERROR(two_link_with("contact:\n  rank_tolerance: 1\n"),
              "x.yaml:10:19:", "contact.rank_tolerance", "must be in (0, 1) (got 1)");
  for (const char* key :
       {"locate_tolerance", "touch_distance", "separation_velocity", "baumgarte_time",
        "initial_penetration", "penetration_tolerance", "detection_margin"}) {
    CAPTURE(key);
    const std::string text = two_link_with("contact:\n") + "  " + key + ": 0\n";
    CHECK_ERROR(text, "x.yaml:10:", std::string("contact.") + key, "must be > 0 (got 0)");
  }
}

TEST_CASE("contact: friction as a number is Coulomb's law with that mu") {
  const Model m = load(two_link_with("contact: {friction: 0.6}\n")).model;
  CHECK(m.contact.friction.law == FrictionLaw::coulomb);
  CHECK(m.contact.friction.mu == doctest::Approx(0.6));
  const Model t = load(two_link_with("contact: {friction: {law: tanh, mu: 0.2}}\n")).model;
  CHECK(t.contact.friction.law == FrictionLaw::tanh);
  CHECK(t.contact.friction.mu == doctest::Approx(0.2));
}

TEST_CASE("contact error: friction") {
  CHECK_ERROR(two_link_with("contact: {friction: {law: coulomb}}\n"), "x.yaml:9:21:",
              "contact.friction.mu", "required key is missing");
  CHECK_ERROR(two_link_with("contact: {friction: {law: viscous, mu: 0.3}}\n"), "x.yaml:9:27:",
              "contact.friction.law", "must be one of coulomb, tanh, saturated");
  CHECK_ERROR(two_link_with("contact: {friction: {mu: 0.3, stick_velocity: 0}}\n"), "x.yaml:9:",
              "contact.friction.stick_velocity", "must be > 0 (got 0)");
  CHECK_ERROR(two_link_with("contact: {friction: {mu: 0.3, slip_speed: 1}}\n"), "x.yaml:9:",
              "contact.friction.slip_speed", "allowed here: law, mu, stick_velocity, tanh_velocity, slip_velocity");
  CHECK_ERROR(two_link_with("contact: {slip_velocity: 1e-4}\n"), "x.yaml:9:",
              "contact.slip_velocity", "moved to contact.friction.slip_velocity");
  CHECK_ERROR(two_link_with("contact:\n  link_warning_depth: 0.01\n"), "x.yaml:10:",
              "contact.link_warning_depth", "replaced by contact.penetration_tolerance");
  CHECK_ERROR(two_link_with("contact: {max_rows: 0}\n"), "x.yaml:9:", "contact.max_rows",
              "must be an integer in 1 .. 100000 (got 0)");
  CHECK_ERROR(two_link_with("validity: {rest_share: 1.5}\n"), "x.yaml:9:", "validity.rest_share",
              "must be in [0, 1] (got 1.5)");
  CHECK_ERROR(two_link_with("validity: {energy_residual: 0}\n"), "x.yaml:9:",
              "validity.energy_residual", "must be > 0 (got 0)");
}

TEST_CASE("contact error: enumerations") {
  CHECK_ERROR(two_link_with("effects: {stabilization: baumgarde}\n"),
              "x.yaml:9:26:", "effects.stabilization",
              "must be one of none, baumgarte, projection (got \"baumgarde\"; did you mean "
              "\"baumgarte\"?)");
  CHECK_ERROR(two_link_with("contact: {events: locat}\n"), "x.yaml:9:19:", "contact.events",
              "must be one of step, locate (got \"locat\"; did you mean \"locate\"?)");
  CHECK_ERROR(two_link_with("effects: {impacts: yes}\n"), "x.yaml:9:20:", "effects.impacts",
              "expected true or false");
}

TEST_CASE("contact error: unknown keys in every new section") {
  CHECK_ERROR(two_link_with("effects: {fricton: true}\n"), "x.yaml:9:11:", "effects.fricton",
              "did you mean \"friction\"");
  CHECK_ERROR(two_link_with("elbows:\n  - {link: 0, at: 0.1, raduis: 0.1}\n"),
              "x.yaml:10:24:", "elbows[0].raduis", "did you mean \"radius\"");
  CHECK_ERROR(two_link_with("table: {box: []}\n"), "x.yaml:9:9:", "table.box",
              "did you mean \"boxes\"");
  CHECK_ERROR(
      two_link_with("table:\n  boxes: [{center: [0, 0, 0], size: [1, 1, 1], rpi: [0, 0, 0]}]\n"),
      "x.yaml:10:", "table.boxes[0].rpi", "did you mean \"rpy\"");
  CHECK_ERROR(two_link_with("contact: {restitusion: 0.5}\n"), "x.yaml:9:11:", "contact.restitusion",
              "did you mean \"restitution\"");
  CHECK_ERROR(two_link_with("elbows: {link: 0}\n"), "x.yaml:9:9:", "elbows", "expected a list");
}

// ---------------------------------------------------------------------------
// The shipped contact scene.

TEST_CASE("shipped scenarios: elbow_rest loads, the elbow touching the table top") {
  Scenario s = load_scenario((scenarios_dir() / "elbow_rest.yaml").string());
  const Model& m = s.model;
  REQUIRE(m.dof == 2);
  CHECK(m.effects.contact);
  CHECK_FALSE(m.effects.friction);
  CHECK(m.effects.stabilization == Stabilization::baumgarte);
  CHECK(m.effects.motor == elbowsim::MotorModel::full);
  CHECK(m.km[0] == doctest::Approx(3.0));
  REQUIRE(m.elbows.size() == 1);
  CHECK(m.elbows[0].link == 0);
  CHECK(approx(m.elbows[0].point, Eigen::Vector3d(0.4, 0, 0)));
  CHECK(m.elbows[0].radius == doctest::Approx(0.03));
  REQUIRE(m.table.size() == 1);
  CHECK(approx(m.table[0].size, Eigen::Vector3d(1.2, 0.8, 0.1)));
  CHECK(approx(m.table[0].rotation, Eigen::Matrix3d::Identity()));
  CHECK(m.table[0].center.x() == doctest::Approx(0.4));

  // The elbow centre at q0 (planar: link 0 at angle q0 from +x toward +z),
  // one radius above the box's top face.
  const double q0 = m.initial.q[0];
  CHECK(q0 == doctest::Approx(-0.3));
  const double elbow_z = 0.4 * std::sin(q0);
  const double top = m.table[0].center.z() + m.table[0].size.z() / 2;
  CHECK(std::abs(elbow_z - m.elbows[0].radius - top) < 1e-12);
  CHECK(approx(m.initial.q, Eigen::Vector2d(-0.3, 0.6)));
  CHECK(m.options.duration == doctest::Approx(2.0));
  CHECK(m.options.step == doctest::Approx(1e-3));
}

TEST_CASE("contact error: an elbow that starts inside the table names the elbow and the depth") {
  // The arm lies along z = 0; this table's top is at z = +0.01, so the elbow
  // sphere (radius 0.03) reaches 0.04 m into it.
  const std::string scene = two_link_with(
      "effects: {contact: true}\n"
      "elbows: [{link: 0, at: 0.3, radius: 0.03}]\n"
      "table: {boxes: [{center: [0.4, 0, -0.04], size: [1.0, 0.6, 0.1]}]}\n");
  CHECK_ERROR(scene, "x.yaml:10:10:", "elbows[0]",
              "is 0.04 m inside table box 0 at the initial pose");
  // Within the tolerance it loads.
  CHECK_NOTHROW(load(scene, {"contact.initial_penetration=0.05"}));
}

// ---------------------------------------------------------------------------
// Compliant pads (elbows[i].pad, contact.pad)

TEST_CASE("contact: contact.pad pads every elbow; an elbow's own pad or `rigid` replaces it") {
  const std::string scene = two_link_with(R"(
effects: {contact: true}
elbows:
  - {name: a, link: 0, at: 0.3}
  - {name: b, link: 1, at: 0.1, pad: {stiffness: 2.0e5, damping: 40, thickness: 0.002}}
  - {name: c, link: 1, at: 0.2, pad: rigid}
contact:
  pad: {stiffness: 4.0e4, damping: 60}
)") + kTable;
  const Model m = load(scene).model;
  REQUIRE(m.elbows.size() == 3);
  CHECK(m.elbows[0].pad.stiffness == 4.0e4);
  CHECK(m.elbows[0].pad.damping == 60);
  CHECK(m.elbows[0].pad.thickness == 0.005);  // the default
  CHECK(m.elbows[1].pad.stiffness == 2.0e5);
  CHECK(m.elbows[1].pad.thickness == 0.002);
  CHECK_FALSE(m.elbows[2].pad.on());
  CHECK(m.has_pads());
  CHECK_FALSE(load(two_link_with("effects: {contact: true}\nelbows: [{link: 0, at: 0.3}]\n") + kTable)
                  .model.has_pads());
}

TEST_CASE("contact error: a pad needs a stiffness, a damping >= 0 and a thickness > 0") {
  const std::string elbows = "effects: {contact: true}\nelbows:\n  - {link: 0, at: 0.3, pad: ";
  CHECK_ERROR((kTwoLink + elbows + "{damping: 5}}\n") + kTable, "x.yaml:11:", "elbows[0].pad.stiffness",
              "required key is missing");
  CHECK_ERROR((kTwoLink + elbows + "{stiffness: 1.0e4, damping: -1}}\n") + kTable, "x.yaml:11:",
              "elbows[0].pad.damping", "must be >= 0");
  CHECK_ERROR((kTwoLink + elbows + "{stiffness: 1.0e4, thickness: 0}}\n") + kTable, "x.yaml:11:",
              "elbows[0].pad.thickness", "must be > 0");
  CHECK_ERROR((kTwoLink + elbows + "soft}\n") + kTable, "x.yaml:11:", "elbows[0].pad",
              "or rigid (got \"soft\")");
  CHECK_ERROR((kTwoLink + elbows + "{stiffness: 1.0e4, mass: 1}}\n") + kTable, "x.yaml:11:",
              "elbows[0].pad.mass", "unknown key");
}

TEST_CASE("contact error: a pad refuses projection and the two reference solvers, at their keys") {
  const std::string padded = "elbows: [{link: 0, at: 0.3}]\ncontact: {pad: {stiffness: 1.0e4}";
  CHECK_ERROR((kTwoLink + "effects: {contact: true, stabilization: projection}\n" + padded + "}\n") + kTable,
              "x.yaml:9:", "effects.stabilization", "use baumgarte or none with pads");
  CHECK_ERROR((kTwoLink + "effects: {contact: true}\n" + padded + ", solver: dense_lu}\n") + kTable,
              "x.yaml:11:", "contact.solver", "use auto, schur or aba with pads");
}

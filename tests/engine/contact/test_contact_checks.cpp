// engine/contact/contact_checks.cpp: check_contacts on its own: a warning when a link
// capsule enters a table box (once per entry), and the drift maxima of resting elbows.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "engine/contact/collision.hpp"
#include "engine/contact/contact_checks.hpp"
#include "engine/contact/detection.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("check_contacts: a link pushed into a box warns once per entry, with link, box, depth, t") {
  //   o---- link 0 ----o               z = 0 (radius 0.02)
  //                      \  q2 = -theta
  //   ====================\==========  box 1, top z = -0.03
  //                        \ link 1 (0.4 m, radius 0.01): depth 0.4 sin(theta) - 0.01 + ...
  Model m = planar_arm({{0.3, 1, 0.15, 0.01}, {0.4, 1, 0.2, 0.01}});
  TableBox side, table;  // box 0 is out of reach, so the warning must name box 1
  side.center = Eigen::Vector3d(-2, 2, -0.1), side.size = Eigen::Vector3d(0.5, 0.5, 0.1);
  table.center = Eigen::Vector3d(0.5, 0, -0.28), table.size = Eigen::Vector3d(2, 2, 0.5);
  m.table = {side, table};
  finalize(m);
  Data data(m);
  data.contact.world = std::make_shared<CollisionWorld>(m);
  // One "step": the log emptied, the arm placed, the checks run.
  const auto step_to = [&](double t, double theta) {
    data.log.clear();
    data.t = t;
    forward_kinematics(m, data, Eigen::Vector2d(0, -theta));
    check_contacts(m, data);
    return data.log.warnings;
  };
  const double in = std::numbers::pi / 6;  // tip at z = -0.2: depth 0.17 + 0.02 (test_collision_bullet)
  auto w = step_to(0.1, in);
  REQUIRE(w.size() == 1);
  CHECK(w[0].kind == Warning::Kind::link_in_table);
  CHECK(w[0].index == 1);
  CHECK(w[0].box == 1);
  CHECK(w[0].t == 0.1);
  CHECK(approx(w[0].value, 0.19, 1e-9));
  CHECK(step_to(0.2, in + 0.01).empty());  // still inside: no new warning
  CHECK(step_to(0.3, in).empty());
  CHECK(step_to(0.4, 0.0).empty());  // out
  CHECK(data.contact.link_inside[1] == 0);
  w = step_to(0.5, in);  // in again: warned again
  REQUIRE(w.size() == 1);
  CHECK(w[0].t == 0.5);
  CHECK(data.contact.link_inside[1] == 1);
}

TEST_CASE("check_contacts: max |C| and max |Cd| over resting elbows only, never decreasing") {
  const ElbowArm arm;
  const Model m = arm.model(0.5 * arm.G1(), 0.0);
  Data data(m);
  const auto check_at = [&](double above, double qd1, bool resting) {
    place(m, data, Eigen::Vector2d(arm.q1 + above / (arm.l1 * std::cos(arm.q1)), arm.q2),
          Eigen::Vector2d(qd1, 0.0), 0.0);
    detect_contacts(m, data);
    data.contact.resting[0] = resting;
    check_contacts(m, data);
    return std::pair{std::abs(data.contact.detected[0].distance), std::abs(normal_speed(m, data, 0))};
  };
  const auto [C1, Cd1] = check_at(2e-6, -0.01, true);
  CHECK(C1 > 1e-6);
  CHECK(data.contact.max_abs_C == C1);
  CHECK(data.contact.max_abs_Cd == Cd1);
  check_at(1e-7, 0.001, true);  // closer and slower: the maxima stay
  CHECK(data.contact.max_abs_C == C1);
  CHECK(data.contact.max_abs_Cd == Cd1);
  check_at(1e-3, 1.0, false);  // far and fast, but not resting: not drift
  CHECK(data.contact.max_abs_C == C1);
  CHECK(data.contact.max_abs_Cd == Cd1);
  const auto [C2, Cd2] = check_at(-5e-6, 0.02, true);  // deeper (inside) and faster
  CHECK(data.contact.max_abs_C == C2);
  CHECK(data.contact.max_abs_Cd == Cd2);
  CHECK(C2 > C1);
  CHECK(data.log.warnings.empty());  // the links stay out of the table
}

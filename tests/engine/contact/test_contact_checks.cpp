// engine/contact/contact_checks.cpp: check_contacts on its own: the drift maxima of resting
// slots. (A link or an elbow in the table is a validity failure: tests/engine/run/test_validity.)
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

// engine/control/inverse_kinematics.cpp: the table plane under a point, solve_ik on its
// own (hand and elbow rows, the posture in the null space, limits), and the plan's IK
// residuals on the paper's 4-link arm.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "engine/control/inverse_kinematics.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "support/approx.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("IK: hand on its targets and the elbow on the table (or at its clearance) within 1e-9 m") {
  for (bool elbow_on : {true, false}) {
    WritingArm arm;
    arm.elbow_on = elbow_on;
    const auto [m, x] = arm.scene();
    const auto plan = make_plan(m, x);
    Data data(m);
    const Elbow& elbow = m.elbows[0];
    const double table_top = m.table[0].center.z() + m.table[0].size.z() / 2;
    double hand_worst = 0, elbow_worst = 0;
    for (std::size_t k = 0; k < plan->q.size(); k += 10) {
      forward_kinematics(m, data, plan->q[k]);
      hand_worst = std::max(hand_worst, (point_position(data, m.hand_link, m.hand_point) - plan->hand[k]).norm());
      const double gap = point_position(data, elbow.link, elbow.point).z() - elbow.radius - table_top;
      elbow_worst = std::max(elbow_worst, std::abs(gap - x.task.elbow_clearance));
    }
    CAPTURE(elbow_on);
    MESSAGE("IK residuals: hand ", hand_worst, " m, elbow ", elbow_worst, " m");
    CHECK(hand_worst < 1e-9);
    CHECK(elbow_worst < 1e-9);
    // The hand really moves along the 6 cm line.
    CHECK((plan->hand.back() - plan->hand.front()).norm() == doctest::Approx(std::hypot(0.06, 0.02)));
  }
}

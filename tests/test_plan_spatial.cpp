// The plan's inverse kinematics on a spatial redundant arm with two planned
// elbows (scenarios/hard/spatial_two_elbows.yaml: 7 joints, the elbow joint
// and the forearm resting on the table): a moving hand path held to 1e-9 m,
// and the three ways a plan cannot be made told apart: out of reach (with the
// distance), out of reach within the joint limits, at a singular pose.
#include <doctest/doctest.h>

#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/kinematics.hpp"

using namespace elbowsim;

namespace {

const std::string kSpatial =
    std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/hard/spatial_two_elbows.yaml";

std::string plan_error(const std::vector<std::string>& overrides) {
  const Scenario s = load_scenario(kSpatial, overrides);
  try {
    make_plan(s.model, s.experiment);
  } catch (const PlanError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("plan: a 7-joint spatial arm on two elbows holds a moving hand path to 1e-9 m") {
  // A 3 cm circle in the table's plane around the hand's start, drawn in 2 s,
  // both elbows kept on their planes (5 rows on 7 joints: two free directions,
  // which go to the posture). The IK meets its rows to 1e-8 x the arm's size
  // (0.7 m: 7 nm) at worst; it ends at rounding (~1e-15 m), so 1e-9 m holds
  // with room.
  const Scenario s =
      load_scenario(kSpatial, {"task.path=circle", "task.points=null", "task.center=[-0.015, 0, 0]",
                               "task.radius=0.015", "task.normal=[0, 0, 1]", "task.start_angle=0"});
  const auto plan = make_plan(s.model, s.experiment);
  REQUIRE(plan->q.size() > 2000);
  Data data(s.model);
  double hand = 0, elbows = 0, moved = 0;
  for (std::size_t k = 0; k < plan->q.size(); ++k) {
    forward_kinematics(s.model, data, plan->q[k]);
    hand = std::max(
        hand, (point_position(data, s.model.hand_link, s.model.hand_point) - plan->hand[k]).norm());
    moved = std::max(moved, (plan->hand[k] - plan->hand[0]).norm());
    for (const Elbow& e : s.model.elbows) {
      const TableBox& box = s.model.table[0];
      const double top = box.center.z() + box.size.z() / 2;
      elbows =
          std::max(elbows, std::abs(point_position(data, e.link, e.point).z() - e.radius - top));
    }
  }
  MESSAGE("hand ", hand, " m, elbows ", elbows, " m off over ", plan->q.size(),
          " samples; the hand moves ", moved, " m");
  CHECK(moved > 0.029);  // the whole circle, 3 cm across
  CHECK(hand < 1e-9);
  CHECK(elbows < 1e-9);
}

TEST_CASE("plan: out of reach names the time and the distance; within joint limits says so") {
  // Half a metre away: beyond the arm's 0.7 m with both elbows down.
  const std::string far = plan_error({"task.points=[start, [0.5, 0, 0]]"});
  INFO(far);
  CHECK(has(far, "is out of reach: missed by "));
  CHECK(has(far, "at t = "));
  CHECK(has(far, "(tolerance "));
  CHECK_FALSE(has(far, "did not converge"));
  // Joint limits as an active set: with the shoulder (joints 0, 1) held
  // within 0.01 rad of its start the 2 cm line is still drawn, and every
  // sample keeps to the limits; with the upper-arm and forearm rolls (2, 4)
  // held too, it is not: out of reach within the joint limits (stationary).
  const std::string shoulder =
      "task.joint_limits={min: [0.29, 0.39, -3, -3, -3, -3, -3], max: [0.31, 0.41, 3, 3, 3, 3, 3]}";
  const Scenario held = load_scenario(kSpatial, {shoulder});
  const auto plan = make_plan(held.model, held.experiment);
  for (const Eigen::VectorXd& q : plan->q) {
    CHECK((q.array() >= held.experiment.task.q_min.array()).all());
    CHECK((q.array() <= held.experiment.task.q_max.array()).all());
  }
  const std::string limited =
      plan_error({"task.joint_limits={min: [-3, -3, 0.49, -3, 0.29, -3, -3], max: [3, 3, 0.51, 3, "
                  "0.31, 3, 3]}"});
  INFO(limited);
  CHECK(has(limited, "is out of reach within the joint limits: missed by "));
}

TEST_CASE("plan: a target at the edge of reach is out of reach at a singular pose, and says so") {
  // Straight out along the upper arm and forearm until stretched: the miss
  // comes with the singular pose's conditioning.
  const std::string stretched = plan_error(
      {"task.elbows=[]", "effects.contact=false", "task.points=[start, [0.6, 0.2, 0.3]]"});
  INFO(stretched);
  CHECK(has(stretched, "out of reach"));
  CHECK(has(stretched, "singular pose"));
}

// robot: base pose, the kinematic chain (planar shorthand or general joints),
// joint damping and the hand point.
#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"

namespace elbowsim::loader {

namespace {

// Exactly one of robot.planar / robot.joints.
void read_chain(const Value& robot, Model& model) {
  Value planar = robot.get("planar");
  Value joints = robot.get("joints");
  if (planar.exists() && joints.exists())
    robot.fail("give exactly one of planar or joints (got both)");
  if (planar.exists()) {
    read_planar_chain(planar, model);
  } else if (joints.exists()) {
    read_general_chain(joints, model);
  } else {
    robot.fail("missing the arm: give exactly one of planar or joints");
  }
  model.dof = static_cast<int>(model.links.size());
}

// One number for all joints, or one per joint; >= 0 [N m s/rad].
Eigen::VectorXd read_damping(const Value& damping, int dof) {
  if (!damping.present()) return Eigen::VectorXd::Zero(dof);
  if (!damping.is_sequence()) return Eigen::VectorXd::Constant(dof, non_negative(damping));
  Eigen::VectorXd d = per_joint(damping, dof);
  std::vector<Value> items = damping.items();
  for (int i = 0; i < dof; ++i) non_negative(items[static_cast<std::size_t>(i)]);
  return d;
}

// hand: {link: index (negative counts from the end), point: [x, y, z] in that
// link's frame}; default: the tip of the last link.
void read_hand(const Value& hand, Model& model) {
  const int n = model.dof;
  long link = -1;
  if (hand.present()) {
    hand.allow_keys({"link", "point"});
    Value index = hand.get("link");
    link = value_or(index, -1L, [](const Value& v) { return v.integer(); });
    if (link < -n || link >= n)
      index.fail("link index out of range (got " + std::to_string(link) + "; the robot has " +
                 std::to_string(n) + " links: " + std::to_string(-n) + " .. " +
                 std::to_string(n - 1) + ")");
  }
  model.hand_link = static_cast<int>(link < 0 ? link + n : link);
  Eigen::Vector3d tip = model.links[static_cast<std::size_t>(model.hand_link)].tip;
  model.hand_point = hand.present() ? value_or(hand.get("point"), tip, vec3) : tip;
}

}  // namespace

void read_robot(const Value& robot, Model& model) {
  robot.allow_keys({"base", "planar", "joints", "damping", "hand"});
  model.base = value_or(robot.get("base"), Eigen::Isometry3d::Identity(), pose);
  read_chain(robot, model);
  model.damping = read_damping(robot.get("damping"), model.dof);
  read_hand(robot.get("hand"), model);
}

}  // namespace elbowsim::loader

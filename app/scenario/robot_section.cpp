// robot: base pose, the kinematic chain (planar shorthand, general joints or a
// URDF), joint damping and the hand point; and the links the scenario names.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

// Exactly one of robot.planar / robot.joints / robot.urdf.
RobotInfo read_chain(const Value& robot, Model& model, const std::string& scenario_file) {
  const Value planar = robot.get("planar"), joints = robot.get("joints"), urdf = robot.get("urdf");
  const int forms = int(planar.exists()) + int(joints.exists()) + int(urdf.exists());
  if (forms > 1) robot.fail("give exactly one of planar, joints or urdf (got " + std::to_string(forms) + ")");
  if (!urdf.exists())
    for (const char* key : {"base_link", "tip_link"})
      if (robot.get(key).exists()) robot.get(key).fail("is only for robot.urdf");
  RobotInfo info;
  if (planar.exists()) {
    info.form = RobotInfo::Form::planar;
    read_planar_chain(planar, model);
  } else if (joints.exists()) {
    read_general_chain(joints, model);
  } else if (urdf.exists()) {
    info = read_urdf_chain(robot, model, scenario_file);
  } else {
    robot.fail("missing the arm: give exactly one of planar, joints or urdf");
  }
  model.dof = static_cast<int>(model.links.size());
  return info;
}

// One number for all joints, or one per joint; >= 0 [N m s/rad]. Default: the
// URDF's <dynamics damping> (already in model.damping), else 0.
Eigen::VectorXd read_damping(const Value& damping, const Model& model) {
  const int dof = model.dof;
  if (!damping.present())
    return model.damping.size() == dof ? model.damping : Eigen::VectorXd::Zero(dof);
  if (!damping.is_sequence()) return Eigen::VectorXd::Constant(dof, non_negative(damping));
  Eigen::VectorXd d = per_joint(damping, dof);
  std::vector<Value> items = damping.items();
  for (int i = 0; i < dof; ++i) non_negative(items[static_cast<std::size_t>(i)]);
  return d;
}

bool is_index(const std::string& text);

// hand: {link: index or URDF link name, point: [x, y, z] in that link's
// frame}. Without a point: an index's link tip, a named link's origin.
// Default: the tip of the last link (with robot.urdf, the tip link's origin).
void read_hand(const Value& hand, Model& model, const RobotInfo& info) {
  model.hand_link = model.dof - 1;
  model.hand_point = model.links.back().tip;
  if (!hand.present()) return;
  hand.allow_keys({"link", "point"});
  const Value link = hand.get("link"), point = hand.get("point");
  RobotInfo::Frame frame{model.dof - 1, Eigen::Isometry3d::Identity()};
  if (link.present()) frame = read_link_frame(link, model, info);
  model.hand_link = frame.link;
  if (point.present())
    model.hand_point = frame.to_link * point.vec3();
  else if (link.present() && !is_index(link.text()))
    model.hand_point = frame.to_link.translation();
  else
    model.hand_point = model.links[static_cast<std::size_t>(frame.link)].tip;
}

bool is_index(const std::string& text) {
  std::size_t k = text.size() > 1 && text[0] == '-' ? 1 : 0;
  if (k == text.size()) return false;
  for (; k < text.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(text[k]))) return false;
  return true;
}

std::string link_range(int n) {
  return "the robot has " + counted(n, "link") + ": " + std::to_string(-n) + " .. " +
         std::to_string(n - 1);
}

// A URDF link name among the chain's.
RobotInfo::Frame named_link(const Value& v, const RobotInfo& robot) {
  const std::string name = v.text();
  const auto at = robot.frames.find(name);
  if (at == robot.frames.end()) {
    std::vector<std::string_view> names;
    for (const std::string& l : robot.names.links) names.push_back(l);
    const std::string guess = closest(name, names);
    v.fail("no link named \"" + name + "\" on the chain of " + robot.names.urdf + " (its moving links: " +
           join(names) + (guess.empty() ? "" : "; did you mean \"" + guess + "\"?") + ")");
  }
  if (at->second.link < 0)
    v.fail("link \"" + name + "\" of " + robot.names.urdf + " is fixed to the base link \"" +
           robot.names.base_link + "\": it never moves");
  return at->second;
}

}  // namespace

RobotInfo::Frame read_link_frame(const Value& v, const Model& model, const RobotInfo& robot) {
  const int n = model.dof;
  if (robot.form == RobotInfo::Form::urdf && !is_index(v.text())) return named_link(v, robot);
  const long link = v.integer();
  if (link < -n || link >= n)
    v.fail("link index out of range (got " + std::to_string(link) + "; " + link_range(n) + ")");
  return {static_cast<int>(link < 0 ? link + n : link), Eigen::Isometry3d::Identity()};
}

RobotInfo read_robot(const Value& robot, Model& model, const std::string& scenario_file) {
  robot.allow_keys({"base", "planar", "joints", "urdf", "base_link", "tip_link", "damping", "hand"});
  model.base = value_or(robot.get("base"), Eigen::Isometry3d::Identity(), pose);
  RobotInfo info = read_chain(robot, model, scenario_file);
  model.damping = read_damping(robot.get("damping"), model);
  read_hand(robot.get("hand"), model, info);
  return info;
}


// springs: [{joint, torque, stiffness, at}], torsion springs at the joints (a
// counterbalance). The joint by index, or by name for robot.urdf.
std::vector<JointSpring> read_springs(const Value& springs, const Model& model,
                                      const RobotInfo& robot) {
  std::vector<JointSpring> out;
  if (!springs.present()) return out;
  for (const Value& v : springs.items()) {
    v.allow_keys({"joint", "torque", "stiffness", "at"});
    JointSpring s;
    const Value joint = v.require("joint");
    const std::vector<std::string>& names = robot.names.joints;
    const std::string text = joint.text();
    const auto named = std::find(names.begin(), names.end(), text);
    const bool index = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+';
    });
    if (named != names.end()) {
      s.joint = static_cast<int>(named - names.begin());
    } else if (!index) {
      joint.fail("names no joint of the arm (" +
                 (names.empty() ? "give an index, 0 .. " + std::to_string(model.dof - 1)
                                : "its joints: " + join({names.begin(), names.end()})) + ")");
    } else {
      const long j = joint.integer();
      if (j < 0 || j >= model.dof)
        joint.fail("must be a joint of the arm, 0 .. " + std::to_string(model.dof - 1) + " (got " +
                   std::to_string(j) + ")");
      s.joint = static_cast<int>(j);
    }
    s.torque = v.require("torque").number();
    s.stiffness = value_or(v.get("stiffness"), 0.0, non_negative);
    s.at = value_or(v.get("at"), 0.0, number);
    out.push_back(s);
  }
  return out;
}

}  // namespace elbowsim::loader

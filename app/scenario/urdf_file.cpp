// URDF text -> urdf::Tree with urdfdom, the ROS project's URDF parser (Debian's
// liburdfdom-dev): the only file that includes it. urdfdom reports what it
// rejects through console_bridge's log; a handler catches those lines for the
// error message instead of letting them reach stderr.
#include "app/scenario/urdf_file.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <mutex>

#include "app/scenario/checks.hpp"

namespace elbowsim::urdf {

const char* to_string(Joint::Type type) {
  switch (type) {
    case Joint::Type::revolute: return "revolute";
    case Joint::Type::continuous: return "continuous";
    case Joint::Type::prismatic: return "prismatic";
    case Joint::Type::fixed: return "fixed";
    case Joint::Type::floating: return "floating";
    case Joint::Type::planar: return "planar";
    case Joint::Type::unknown: return "unknown";
  }
  return "?";
}

namespace {

// Collects urdfdom's error lines while one parse runs.
class Collector : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) lines.push_back(text);
  }
  std::vector<std::string> lines;
};

// urdfdom keeps a rotation as a quaternion only: an angle read back from it
// is off by ~1e-16 rad (pi/2 comes back 2 ulp high). One within 1e-12 rad of
// a multiple of pi/2, the angles frames are mostly turned by, is taken as that
// multiple, so that such a URDF and the YAML general form written with the
// same numbers give the same matrices bit for bit.
double snapped(double angle) {
  const double quarter = 1.5707963267948966;  // pi/2
  const double k = std::round(angle / quarter);
  return std::abs(angle - k * quarter) <= 1e-12 ? k * quarter : angle;
}

// The pose as a transform; the rotation through the scenario's own rpy
// convention (R = Rz Ry Rx).
Eigen::Isometry3d transform(const ::urdf::Pose& p) {
  Eigen::Vector3d rpy;
  p.rotation.getRPY(rpy.x(), rpy.y(), rpy.z());
  for (int k = 0; k < 3; ++k) rpy[k] = snapped(rpy[k]);
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = loader::rpy_rotation(rpy);
  out.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  return out;
}

Collision collision(const ::urdf::Collision& c) {
  Collision out;
  out.origin = transform(c.origin);
  const ::urdf::Geometry& g = *c.geometry;
  switch (g.type) {
    case ::urdf::Geometry::SPHERE:
      out.shape = Collision::Shape::sphere;
      out.radius = static_cast<const ::urdf::Sphere&>(g).radius;
      break;
    case ::urdf::Geometry::BOX: {
      out.shape = Collision::Shape::box;
      const ::urdf::Vector3& d = static_cast<const ::urdf::Box&>(g).dim;
      out.size = Eigen::Vector3d(d.x, d.y, d.z);
      break;
    }
    case ::urdf::Geometry::CYLINDER:
      out.shape = Collision::Shape::cylinder;
      out.radius = static_cast<const ::urdf::Cylinder&>(g).radius;
      out.length = static_cast<const ::urdf::Cylinder&>(g).length;
      break;
    case ::urdf::Geometry::MESH: out.shape = Collision::Shape::mesh; break;
  }
  return out;
}

Link link(const ::urdf::Link& l) {
  Link out;
  out.name = l.name;
  if (l.inertial) {
    const ::urdf::Inertial& i = *l.inertial;
    out.has_inertial = true;
    out.inertial.origin = transform(i.origin);
    out.inertial.mass = i.mass;
    out.inertial.inertia << i.ixx, i.ixy, i.ixz,  //
        i.ixy, i.iyy, i.iyz,                      //
        i.ixz, i.iyz, i.izz;
  }
  for (const ::urdf::CollisionSharedPtr& c : l.collision_array)
    if (c && c->geometry) out.collisions.push_back(collision(*c));
  if (out.collisions.empty() && l.collision && l.collision->geometry)
    out.collisions.push_back(collision(*l.collision));
  return out;
}

Joint::Type type(int t) {
  switch (t) {
    case ::urdf::Joint::REVOLUTE: return Joint::Type::revolute;
    case ::urdf::Joint::CONTINUOUS: return Joint::Type::continuous;
    case ::urdf::Joint::PRISMATIC: return Joint::Type::prismatic;
    case ::urdf::Joint::FIXED: return Joint::Type::fixed;
    case ::urdf::Joint::FLOATING: return Joint::Type::floating;
    case ::urdf::Joint::PLANAR: return Joint::Type::planar;
    default: return Joint::Type::unknown;
  }
}

Joint joint(const ::urdf::Joint& j) {
  Joint out;
  out.name = j.name;
  out.type = type(j.type);
  out.parent = j.parent_link_name;
  out.child = j.child_link_name;
  out.origin = transform(j.parent_to_joint_origin_transform);
  out.axis = Eigen::Vector3d(j.axis.x, j.axis.y, j.axis.z);
  if (j.dynamics) {
    out.damping = j.dynamics->damping;
    out.friction = j.dynamics->friction;
  }
  if (j.limits) {
    out.has_limits = true;
    out.lower = j.limits->lower;
    out.upper = j.limits->upper;
  }
  out.mimics = j.mimic != nullptr;
  return out;
}

// urdfdom's parse with its log caught. console_bridge's handler is global:
// one parse at a time.
::urdf::ModelInterfaceSharedPtr parse_caught(const std::string& xml, std::vector<std::string>& log) {
  static std::mutex mutex;
  const std::lock_guard<std::mutex> lock(mutex);
  Collector collector;
  console_bridge::useOutputHandler(&collector);
  ::urdf::ModelInterfaceSharedPtr model;
  try {
    model = ::urdf::parseURDF(xml);
  } catch (const std::exception& e) {  // urdfdom throws on some attributes (a bad version)
    collector.lines.push_back(e.what());
    model.reset();
  }
  console_bridge::restorePreviousOutputHandler();
  log = collector.lines;
  return model;
}

}  // namespace

Tree parse(const std::string& xml) {
  std::vector<std::string> log;
  const ::urdf::ModelInterfaceSharedPtr model = parse_caught(xml, log);
  if (!model) {
    std::string why;
    for (const std::string& line : log) why += (why.empty() ? "" : "; ") + line;
    throw UrdfError("urdfdom rejects it: " + (why.empty() ? std::string("no reason given") : why));
  }
  Tree tree;
  tree.robot_name = model->getName();
  tree.root = model->getRoot() ? model->getRoot()->name : std::string();
  for (const auto& [name, l] : model->links_) tree.links[name] = link(*l);
  for (const auto& [name, j] : model->joints_) {
    tree.joints[name] = joint(*j);
    tree.children[j->parent_link_name].push_back(name);
    tree.parent_joint[j->child_link_name] = name;
  }
  return tree;
}

}  // namespace elbowsim::urdf

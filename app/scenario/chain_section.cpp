// robot.planar and robot.joints: the joints and links of the arm.
//
// Planar shorthand (docs/conventions.md): the arm lies in the x-z plane, every joint
// axis is -y (a positive angle turns +x toward +z), joint i sits at the tip of
// link i-1, and each link's frame has x along the link:
//
//   z                              joint i origin = (length_{i-1}, 0, 0)
//   |           link 1             link com       = (com, 0, 0)
//   |     j1 o---------o tip       link tip       = (length, 0, 0)
//   |       /                      inertia about the com = diag(m r^2/2, I, I)
//   |      / link 0                (I: the planar inertia, r: the radius)
//   |  j0 o---------- x
#include <Eigen/Eigenvalues>
#include <cmath>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

const Eigen::Vector3d kPlanarAxis(0, -1, 0);
constexpr double kDefaultRadius = 0.02;  // [m]

// The chain: 1 .. kMaxJoints entries. The engine's per-run state holds dense
// dof x dof matrices (mass matrix, its Cholesky factor, ...) sized when a run (and
// the loader's initial-penetration check) starts: 20 000 joints asked for 12.8 GB
// (a hand-made input run through tests/fuzz/). The count is checked before any
// entry is read.
std::vector<Value> chain_list(const Value& list) {
  std::vector<Value> items = list.items();
  if (items.empty()) list.fail("needs at least one entry");
  if (items.size() > static_cast<std::size_t>(kMaxJoints))
    list.fail("has " + std::to_string(items.size()) + " entries; at most " +
              std::to_string(kMaxJoints) + " joints are supported");
  return items;
}

// A rigid body's inertia about its com: positive definite, and its principal
// moments a <= b <= c satisfy a + b >= c (relative tolerance 1e-12).
void check_inertia(const Eigen::Matrix3d& inertia, const Value& at) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  const Eigen::Vector3d m = eig.eigenvalues();  // ascending
  if (!(m[0] > 0))
    at.fail("must be positive definite (principal moments " + listed({m[0], m[1], m[2]}) + ")");
  if (m[0] + m[1] < m[2] - 1e-12 * inertia.trace())
    at.fail("violates the triangle inequality: principal moments " + significant(m[0]) + " + " +
            significant(m[1]) + " < " + significant(m[2]) + " (no rigid body has them)");
}

// --- planar ----------------------------------------------------------------

struct PlanarLink {
  double length = 0;
  Link link;
};

// The rod's moments diag(m r^2/2, I, I) are a rigid body's only if I >= m r^2/4
// (triangle inequality). Blames the inertia if given, else the radius, else
// the link.
void check_planar_inertia(const Value& v, const Link& link, double planar) {
  const double m = link.mass, r = link.radius;
  if (planar >= m * r * r / 4 * (1 - 1e-12)) return;
  const std::string min_inertia = "I >= m r^2/4 = " + significant(m * r * r / 4) + " kg m^2";
  if (v.get("inertia").present())
    v.get("inertia").fail("is too small for the link's radius " + significant(r) + " m: needs " +
                          min_inertia + " (got " + significant(planar) + ")");
  const std::string max_radius = "r <= 2 sqrt(I/m) = " + significant(2 * std::sqrt(planar / m)) +
                                 " m for I = " + significant(planar) + " kg m^2";
  if (v.get("radius").present())
    v.get("radius").fail("is too large for the link: needs " + max_radius);
  v.fail("the link is too short for the default radius " + significant(r) +
         " m: give a radius with " + max_radius + ", or an inertia with " + min_inertia);
}

// {capsule: {from: [x, y, z], to: [x, y, z], radius: r}} (link frame).
LinkCollision read_capsule(const Value& c) {
  c.allow_keys({"from", "to", "radius"});
  LinkCollision out;
  out.from = c.require("from").vec3();
  out.to = c.require("to").vec3();
  out.radius = positive(c.require("radius"));
  return out;
}

// collision: capsule (the default: origin to tip, the link's radius) | none |
// {capsule: {from, to, radius}} | {sphere: {center: [x, y, z], radius: r}} |
// {box: {center: [x, y, z], size: [a, b, c]}} (link frame; a box along the
// link frame's axes).
LinkCollision read_collision(const Value& v) {
  LinkCollision out;
  if (!v.present()) return out;
  if (!v.is_map()) {
    const std::string kind = v.text();
    if (kind == "capsule") return out;
    if (kind == "none") {
      out.kind = LinkCollision::Kind::none;
      return out;
    }
    v.fail("must be capsule, none, {capsule: {from, to, radius}}, {sphere: {center, radius}} or "
           "{box: {center, size}} (got " + kind + ")");
  }
  v.allow_keys({"capsule", "sphere", "box"});
  const int kinds = int(v.get("capsule").present()) + int(v.get("sphere").present()) +
                    int(v.get("box").present());
  if (kinds != 1) v.fail("needs exactly one of capsule:, sphere: or box:");
  if (v.get("capsule").present()) return read_capsule(v.get("capsule"));
  if (v.get("sphere").present()) {
    const Value s = v.get("sphere");
    s.allow_keys({"center", "radius"});
    out.kind = LinkCollision::Kind::sphere;
    out.center = value_or(s.get("center"), Eigen::Vector3d::Zero().eval(), vec3);
    out.radius = positive(s.require("radius"));
    return out;
  }
  const Value b = v.get("box");
  b.allow_keys({"center", "size"});
  out.kind = LinkCollision::Kind::box;
  out.center = value_or(b.get("center"), Eigen::Vector3d::Zero().eval(), vec3);
  out.size = b.require("size").vec3();
  if (!(out.size.array() > 0).all()) b.get("size").fail("must be three positive lengths [m]");
  return out;
}

PlanarLink read_planar_link(const Value& v) {
  v.allow_keys({"length", "mass", "com", "inertia", "radius", "collision"});
  PlanarLink out;
  Link& link = out.link;
  out.length = positive(v.require("length"));
  link.mass = positive(v.require("mass"));
  const double length = out.length, mass = link.mass;
  link.com = Eigen::Vector3d(value_or(v.get("com"), length / 2, number), 0, 0);
  const double planar = value_or(v.get("inertia"), mass * length * length / 12, positive);
  link.radius = value_or(v.get("radius"), kDefaultRadius, positive);
  check_planar_inertia(v, link, planar);
  link.inertia = Eigen::Vector3d(mass * link.radius * link.radius / 2, planar, planar).asDiagonal();
  link.tip = Eigen::Vector3d(length, 0, 0);
  link.collision = read_collision(v.get("collision"));
  return out;
}

// --- general ---------------------------------------------------------------

// {ixx, iyy, izz, ixy = 0, ixz = 0, iyz = 0} [kg m^2], about the com.
Eigen::Matrix3d read_inertia(const Value& v) {
  v.allow_keys({"ixx", "iyy", "izz", "ixy", "ixz", "iyz"});
  const double ixx = number(v.require("ixx"));
  const double iyy = number(v.require("iyy"));
  const double izz = number(v.require("izz"));
  const double ixy = value_or(v.get("ixy"), 0.0, number);
  const double ixz = value_or(v.get("ixz"), 0.0, number);
  const double iyz = value_or(v.get("iyz"), 0.0, number);
  Eigen::Matrix3d inertia;
  inertia << ixx, ixy, ixz,  //
      ixy, iyy, iyz,         //
      ixz, iyz, izz;
  check_inertia(inertia, v);
  return inertia;
}

Link read_link(const Value& v) {
  v.allow_keys({"mass", "com", "inertia", "radius", "tip", "collision"});
  Link link;
  link.mass = positive(v.require("mass"));
  link.com = value_or(v.get("com"), Eigen::Vector3d::Zero().eval(), vec3);
  link.inertia = read_inertia(v.require("inertia"));
  link.radius = value_or(v.get("radius"), kDefaultRadius, positive);
  link.tip = value_or(v.get("tip"), Eigen::Vector3d::Zero().eval(), vec3);
  link.collision = read_collision(v.get("collision"));
  return link;
}

// Non-zero direction, normalized; default +z.
Eigen::Vector3d read_axis(const Value& v) {
  if (!v.present()) return Eigen::Vector3d::UnitZ();
  Eigen::Vector3d axis = v.vec3();
  if (!(axis.norm() > 1e-12)) v.fail("must be a non-zero direction");
  return axis.normalized();
}

}  // namespace

void read_planar_chain(const Value& planar, Model& model) {
  planar.allow_keys({"links"});
  double previous_length = 0;
  for (const Value& v : chain_list(planar.require("links"))) {
    PlanarLink p = read_planar_link(v);
    Joint joint;
    joint.origin_position = Eigen::Vector3d(previous_length, 0, 0);
    joint.axis = kPlanarAxis;
    model.joints.push_back(joint);
    model.links.push_back(p.link);
    previous_length = p.length;
  }
}

void read_general_chain(const Value& joints, Model& model) {
  for (const Value& v : chain_list(joints)) {
    v.allow_keys({"origin", "axis", "link"});
    const Eigen::Isometry3d origin = value_or(v.get("origin"), Eigen::Isometry3d::Identity(), pose);
    Joint joint;
    joint.origin_rotation = origin.linear();
    joint.origin_position = origin.translation();
    joint.axis = read_axis(v.get("axis"));
    model.joints.push_back(joint);
    model.links.push_back(read_link(v.require("link")));
  }
}

}  // namespace elbowsim::loader

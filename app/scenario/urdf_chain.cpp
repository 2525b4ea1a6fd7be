#include "app/scenario/urdf_chain.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "app/scenario/scenario.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::urdf {

namespace {

constexpr double kDefaultRadius = 0.02;  // [m] drawing radius of a link without a solid

std::string in_quotes(const std::string& name) { return "\"" + name + "\""; }

// A rigid body: a moving link (or the base link) and every link fixed to it,
// each with its pose in the body's frame; the moving joints that leave it.
struct Body {
  struct Member {
    const Link* link;
    Eigen::Isometry3d pose;  // member frame in the body frame
  };
  std::vector<Member> members;  // the body's own link first
  struct Exit {
    const Joint* joint;
    Eigen::Isometry3d parent_pose;  // the joint's parent link frame in the body frame
  };
  std::vector<Exit> exits;
};

const Link& find_link(const Tree& tree, const std::string& name) {
  const auto it = tree.links.find(name);
  if (it == tree.links.end()) throw UrdfError("no link named " + in_quotes(name));
  return it->second;
}

// Depth first through fixed joints from `root`.
Body body_of(const Tree& tree, const std::string& root) {
  Body body;
  std::vector<Body::Member> stack{{&find_link(tree, root), Eigen::Isometry3d::Identity()}};
  while (!stack.empty()) {
    const Body::Member m = stack.back();
    stack.pop_back();
    body.members.push_back(m);
    const auto children = tree.children.find(m.link->name);
    if (children == tree.children.end()) continue;
    for (const std::string& name : children->second) {
      const Joint& j = tree.joints.at(name);
      if (j.type == Joint::Type::fixed)
        stack.push_back({&find_link(tree, j.child), m.pose * j.origin});
      else
        body.exits.push_back({&j, m.pose});
    }
  }
  return body;
}

// --- the rigid body's inertia ------------------------------------------------

void check_inertial(const Link& l) {
  const double m = l.inertial.mass;
  if (!(m > 0) || !std::isfinite(m))
    throw UrdfError("link " + in_quotes(l.name) + ": <inertial><mass value=\"" + significant(m) +
                    "\"/> must be > 0");
}

// Positive definite, and principal moments a <= b <= c with a + b >= c.
void check_inertia(const Eigen::Matrix3d& inertia, const std::string& what) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  const Eigen::Vector3d m = eig.eigenvalues();
  const std::string moments = listed({m[0], m[1], m[2]});
  if (!inertia.allFinite() || !(m[0] > 0))
    throw UrdfError(what + ": <inertia> must be positive definite (principal moments " + moments +
                    ")");
  if (m[0] + m[1] < m[2] - 1e-12 * inertia.trace())
    throw UrdfError(what + ": <inertia> violates the triangle inequality (principal moments " +
                    moments + "): no rigid body has it");
}

// Mass, centre of mass and inertia about it of the body's members with an
// <inertial> (link frame). One member: its numbers as written, untouched.
void add_inertia(const Body& body, elbowsim::Link& out) {
  std::vector<const Body::Member*> massive;
  for (const Body::Member& m : body.members)
    if (m.link->has_inertial) check_inertial(*m.link), massive.push_back(&m);
  const std::string& name = body.members.front().link->name;
  if (massive.empty())
    throw UrdfError("link " + in_quotes(name) +
                    ": no <inertial> (a moving link needs its mass and inertia" +
                    (body.members.size() > 1 ? ", on it or on a link fixed to it)" : ")"));
  std::string what = "link " + in_quotes(name);
  if (massive.size() == 1) {
    const Body::Member& m = *massive.front();
    const Eigen::Matrix3d R = m.pose.linear() * m.link->inertial.origin.linear();
    out.mass = m.link->inertial.mass;
    out.com = m.pose * m.link->inertial.origin.translation();
    out.inertia = R.isIdentity(0) ? m.link->inertial.inertia
                                  : Eigen::Matrix3d(R * m.link->inertial.inertia * R.transpose());
    if (m.link != body.members.front().link) what = "link " + in_quotes(m.link->name);
    return check_inertia(out.inertia, what);
  }
  out.mass = 0;
  out.com.setZero();
  for (const Body::Member* m : massive) {
    out.mass += m->link->inertial.mass;
    out.com += m->link->inertial.mass * (m->pose * m->link->inertial.origin.translation());
  }
  out.com /= out.mass;
  out.inertia.setZero();
  for (const Body::Member* m : massive) {
    const Inertial& in = m->link->inertial;
    const Eigen::Matrix3d R = m->pose.linear() * in.origin.linear();
    const Eigen::Vector3d d = m->pose * in.origin.translation() - out.com;
    check_inertia(in.inertia, "link " + in_quotes(m->link->name));
    // Parallel axes: each member's inertia turned into the body frame and moved to the com.
    out.inertia += R * in.inertia * R.transpose() +
                   in.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  check_inertia(out.inertia, what + " with the links fixed to it");
}

// --- the rigid body's solid against the table --------------------------------

// A box turned by a multiple of 90 degrees about the link's axes: its edges
// along the link frame's axes (the engine's boxes are), else a UrdfError.
Eigen::Vector3d aligned_size(const Eigen::Matrix3d& R, const Eigen::Vector3d& size,
                             const std::string& link) {
  const Eigen::Matrix3d A = R.cwiseAbs();
  for (int c = 0; c < 3; ++c) {
    Eigen::Index row;
    const double largest = A.col(c).maxCoeff(&row);
    if (std::abs(largest - 1) > 1e-9)
      throw UrdfError("link " + in_quotes(link) +
                      ": <collision><box> is turned off the link frame's axes; elbowsim's "
                      "boxes lie along them (turn it by multiples of 90 degrees only)");
  }
  return A * size;
}

LinkCollision solid(const Collision& c, const Eigen::Isometry3d& pose, const std::string& link) {
  const Eigen::Isometry3d T = pose * c.origin;
  LinkCollision out;
  const std::string at = "link " + in_quotes(link) + ": <collision>";
  switch (c.shape) {
    case Collision::Shape::sphere:
      if (!(c.radius > 0)) throw UrdfError(at + "<sphere radius> must be > 0");
      out.kind = LinkCollision::Kind::sphere;
      out.center = T.translation();
      out.radius = c.radius;
      return out;
    case Collision::Shape::cylinder: {
      if (!(c.radius > 0) || !(c.length >= 0))
        throw UrdfError(at + "<cylinder> needs radius > 0 and length >= 0");
      // The capsule around the cylinder: its axis (origin z) and radius.
      const Eigen::Vector3d half = 0.5 * c.length * T.linear().col(2);
      out.kind = LinkCollision::Kind::capsule;
      out.from = T.translation() - half;
      out.to = T.translation() + half;
      out.radius = c.radius;
      return out;
    }
    case Collision::Shape::box:
      if (!(c.size.array() > 0).all()) throw UrdfError(at + "<box size> must be three lengths > 0");
      out.kind = LinkCollision::Kind::box;
      out.center = T.translation();
      out.size = aligned_size(T.linear(), c.size, link);
      return out;
    case Collision::Shape::mesh: break;
  }
  throw UrdfError(at + " is a <mesh>: elbowsim's solids against the table are primitives; give "
                  "a <cylinder> (taken as the capsule around it), <sphere> or <box>");
}

// The body's one solid (none without a <collision>) and its drawing radius.
void add_solid(const Body& body, elbowsim::Link& out) {
  const std::string& name = body.members.front().link->name;
  std::vector<std::string> owners;
  out.collision.kind = LinkCollision::Kind::none;
  out.radius = kDefaultRadius;
  for (const Body::Member& m : body.members)
    for (const Collision& c : m.link->collisions) {
      owners.push_back(m.link->name);
      out.collision = solid(c, m.pose, m.link->name);
    }
  if (owners.size() > 1) {
    std::string list;
    for (const std::string& o : owners) list += (list.empty() ? "" : ", ") + in_quotes(o);
    throw UrdfError("link " + in_quotes(name) + " carries " + std::to_string(owners.size()) +
                    " <collision> solids (on links " + list +
                    "); elbowsim takes one solid per moving link and the links fixed to it");
  }
  if (out.collision.kind == LinkCollision::Kind::sphere ||
      out.collision.kind == LinkCollision::Kind::capsule)
    out.radius = out.collision.radius;
  if (out.collision.kind == LinkCollision::Kind::box)
    out.radius = 0.5 * out.collision.size.minCoeff();
}

// --- the chain ----------------------------------------------------------------

// The one moving joint that leaves `body`; throws at a branch.
const Body::Exit* next_exit(const Body& body) {
  if (body.exits.empty()) return nullptr;
  if (body.exits.size() == 1) return &body.exits.front();
  const Joint& a = *body.exits[0].joint;
  const Joint& b = *body.exits[1].joint;
  const std::string& root = body.members.front().link->name;
  const std::string at = a.parent == b.parent ? "link " + in_quotes(a.parent)
                                              : "the rigid body of link " + in_quotes(root);
  throw UrdfError("the tree branches at " + at + ": joints " + in_quotes(a.name) + " (" +
                  to_string(a.type) + ", to link " + in_quotes(a.child) + ") and " + in_quotes(b.name) +
                  " (" + to_string(b.type) + ", to link " + in_quotes(b.child) +
                  ") both move links below it; elbowsim simulates a serial chain (make the "
                  "branch's joints fixed, or remove the branch)");
}

void check_joint(const Joint& j) {
  const std::string at = "joint " + in_quotes(j.name);
  if (j.type == Joint::Type::prismatic)
    throw UrdfError(at + " is prismatic: elbowsim's joints are revolute (type revolute or "
                         "continuous); make it fixed to import the arm");
  if (j.type != Joint::Type::revolute && j.type != Joint::Type::continuous)
    throw UrdfError(at + " is " + to_string(j.type) +
                    ": elbowsim's joints are revolute (type revolute or continuous)");
  if (j.mimics)
    throw UrdfError(at + " has a <mimic>: elbowsim's joints move independently");
  if (!(j.axis.norm() > 1e-12) || !j.axis.allFinite())
    throw UrdfError(at + ": <axis xyz> must be a non-zero direction");
  if (!(j.damping >= 0) || !std::isfinite(j.damping))
    throw UrdfError(at + ": <dynamics damping> must be >= 0");
  if (j.type == Joint::Type::revolute && !(j.lower < j.upper))
    throw UrdfError(at + ": <limit lower=\"" + significant(j.lower) + "\" upper=\"" +
                    significant(j.upper) + "\"> needs lower < upper");
}

void add_frames(const Body& body, int link, Chain& chain) {
  for (const Body::Member& m : body.members) chain.frames[m.link->name] = {link, m.pose};
}

// Appends joint `exit` and the body it moves; returns that body.
Body add_joint(const Tree& tree, const Body::Exit& exit, Chain& chain) {
  const Joint& j = *exit.joint;
  check_joint(j);
  const Eigen::Isometry3d origin = exit.parent_pose * j.origin;
  elbowsim::Joint joint;
  joint.origin_rotation = origin.linear();
  joint.origin_position = origin.translation();
  joint.axis = j.axis.normalized();
  if (!chain.links.empty()) chain.links.back().tip = joint.origin_position;
  const Body body = body_of(tree, j.child);
  elbowsim::Link link;
  add_inertia(body, link);
  add_solid(body, link);
  const int i = static_cast<int>(chain.joints.size());
  chain.joints.push_back(joint);
  chain.links.push_back(link);
  chain.joint_names.push_back(j.name);
  chain.link_names.push_back(j.child);
  chain.merged.emplace_back();
  for (std::size_t k = 1; k < body.members.size(); ++k)
    chain.merged.back().push_back(body.members[k].link->name);
  add_frames(body, i, chain);
  return body;
}

// Per-joint numbers after the walk: damping, friction, limits.
void add_joint_numbers(const Tree& tree, Chain& chain) {
  const auto n = static_cast<Eigen::Index>(chain.joints.size());
  const double inf = std::numeric_limits<double>::infinity();
  chain.damping.resize(n), chain.friction.resize(n), chain.q_min.resize(n), chain.q_max.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Joint& j = tree.joints.at(chain.joint_names[static_cast<std::size_t>(i)]);
    chain.damping[i] = j.damping;
    chain.friction[i] = j.friction;
    const bool limited = j.type == Joint::Type::revolute;
    chain.q_min[i] = limited ? j.lower : -inf;
    chain.q_max[i] = limited ? j.upper : inf;
  }
}

// The hand's link: the tip link's frame, which must be on the last moving link.
void place_tip(const std::string& tip, Chain& chain) {
  const int last = static_cast<int>(chain.links.size()) - 1;
  chain.tip = tip.empty() ? chain.link_names.back() : tip;
  const auto at = chain.frames.find(chain.tip);
  if (at == chain.frames.end())
    throw UrdfError("tip link " + in_quotes(chain.tip) + " is not on the chain below base link " +
                    in_quotes(chain.base));
  if (at->second.link != last)
    throw UrdfError("tip link " + in_quotes(chain.tip) + " is not the end of the chain: joint " +
                    in_quotes(chain.joint_names[static_cast<std::size_t>(at->second.link + 1)]) +
                    " moves link " +
                    in_quotes(chain.link_names[static_cast<std::size_t>(at->second.link + 1)]) +
                    " beyond it");
  chain.links.back().tip = at->second.to_link.translation();
}

}  // namespace

Chain build_chain(const Tree& tree, const std::string& base, const std::string& tip) {
  Chain chain;
  chain.base = base.empty() ? tree.root : base;
  if (!tree.links.count(chain.base)) throw UrdfError("no link named " + in_quotes(chain.base));
  Body body = body_of(tree, chain.base);
  add_frames(body, -1, chain);
  while (const Body::Exit* exit = next_exit(body)) {
    if (chain.joints.size() >= static_cast<std::size_t>(kMaxJoints))
      throw UrdfError("the chain has more than " + std::to_string(kMaxJoints) +
                      " moving joints, the most elbowsim supports");
    body = add_joint(tree, *exit, chain);
  }
  if (chain.joints.empty())
    throw UrdfError("no revolute or continuous joint below base link " + in_quotes(chain.base));
  add_joint_numbers(tree, chain);
  place_tip(tip, chain);
  return chain;
}

}  // namespace elbowsim::urdf

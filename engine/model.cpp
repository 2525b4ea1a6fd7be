#include "engine/model.hpp"

#include <Eigen/Eigenvalues>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace elbowsim {

const char* to_string(MotorModel m) {
  switch (m) {
    case MotorModel::none: return "none";
    case MotorModel::quasi_static: return "quasi_static";
    case MotorModel::full: return "full";
  }
  return "?";
}

const char* to_string(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::euler: return "euler";
    case IntegratorKind::semi_implicit_euler: return "semi_implicit_euler";
    case IntegratorKind::rk4: return "rk4";
    case IntegratorKind::dopri5: return "dopri5";
    case IntegratorKind::ros34pw2: return "ros34pw2";
  }
  return "?";
}

const char* to_string(ConstraintSolver s) {
  switch (s) {
    case ConstraintSolver::automatic: return "auto";
    case ConstraintSolver::schur: return "schur";
    case ConstraintSolver::aba: return "aba";
    case ConstraintSolver::dense_lu: return "dense_lu";
    case ConstraintSolver::explicit_inverse: return "explicit_inverse";
  }
  return "?";
}

bool is_adaptive(IntegratorKind k) {
  return k == IntegratorKind::dopri5 || k == IntegratorKind::ros34pw2;
}

const char* to_string(DynamicsMethod d) {
  switch (d) {
    case DynamicsMethod::walker_orin: return "walker_orin";
    case DynamicsMethod::crba: return "crba";
    case DynamicsMethod::aba: return "aba";
  }
  return "?";
}

const char* to_string(Stabilization s) {
  switch (s) {
    case Stabilization::none: return "none";
    case Stabilization::baumgarte: return "baumgarte";
    case Stabilization::projection: return "projection";
  }
  return "?";
}

const char* to_string(EventTiming e) {
  switch (e) {
    case EventTiming::step: return "step";
    case EventTiming::locate: return "locate";
  }
  return "?";
}

const char* to_string(FrictionLaw law) {
  switch (law) {
    case FrictionLaw::coulomb: return "coulomb";
    case FrictionLaw::tanh: return "tanh";
    case FrictionLaw::saturated: return "saturated";
  }
  return "?";
}

bool Model::has_pads() const {
  if (!effects.contact) return false;
  for (const Elbow& e : elbows)
    if (e.pad.on()) return true;
  return false;
}

std::vector<std::string> Model::active_effects() const {
  std::vector<std::string> names;
  if (effects.gravity) names.emplace_back("gravity");
  if (effects.damping) names.emplace_back("damping");
  if (has_motor()) names.emplace_back(std::string("motor:") + to_string(effects.motor));
  if (has_armature()) names.emplace_back("rotor_inertia");
  if (effects.joint_friction) names.emplace_back("joint_friction");
  if (has_springs()) names.emplace_back("springs");
  if (effects.contact) {
    names.emplace_back("contact");
    if (effects.friction) names.emplace_back("friction");
    if (effects.impacts) names.emplace_back("impacts");
    if (has_pads()) names.emplace_back("pads");
    if (effects.stabilization != Stabilization::none)
      names.emplace_back(std::string("stabilization:") + to_string(effects.stabilization));
  }
  return names;
}

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("invalid model: " + what);
}

std::string at(const char* member, int i) {
  return std::string(member) + "[" + std::to_string(i) + "]";
}

void check_link(const Link& link, int i) {
  require(link.mass > 0 && std::isfinite(link.mass), at("links", i) + ".mass must be > 0");
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(link.inertia);
  require(link.inertia.isApprox(link.inertia.transpose()) && eig.eigenvalues().minCoeff() > 0,
          at("links", i) + ".inertia must be symmetric positive definite");
  // A rigid body's principal moments satisfy I_a + I_b >= I_c.
  const Eigen::Vector3d I = eig.eigenvalues();
  require(I[0] + I[1] >= I[2] * (1 - 1e-12),
          at("links", i) + ".inertia violates the triangle inequality of principal moments");
  require(link.radius > 0, at("links", i) + ".radius must be > 0");
  require(link.collision.radius >= 0, at("links", i) + ".collision.radius must be >= 0");
}

void check_contact_scene(const Model& model) {
  for (std::size_t k = 0; k < model.elbows.size(); ++k) {
    const Elbow& e = model.elbows[k];
    require(e.link >= 0 && e.link < model.dof, at("elbows", int(k)) + ".link out of range");
    require(e.radius > 0, at("elbows", int(k)) + ".radius must be > 0");
    require(e.pad.stiffness >= 0 && std::isfinite(e.pad.stiffness) && e.pad.damping >= 0 &&
                std::isfinite(e.pad.damping) && e.pad.thickness > 0,
            at("elbows", int(k)) + ".pad needs stiffness >= 0, damping >= 0 and thickness > 0");
  }
  // A pad's row carries a prescribed force, which the projection (a position
  // constraint per resting row) and the two reference solvers do not know.
  require(!model.has_pads() || model.effects.stabilization != Stabilization::projection,
          "a pad needs effects.stabilization baumgarte or none (projection holds every resting row at C = 0)");
  require(!model.has_pads() || (model.contact.solver != ConstraintSolver::dense_lu &&
                                model.contact.solver != ConstraintSolver::explicit_inverse),
          "a pad needs contact.solver auto, schur or aba");
  for (std::size_t b = 0; b < model.table.size(); ++b)
    require((model.table[b].size.array() > 0).all(), at("table", int(b)) + ".size must be > 0");
  const ContactOptions& c = model.contact;
  require(c.restitution >= 0 && c.restitution <= 1, "contact.restitution must be in [0, 1]");
  require(c.friction.mu >= 0, "contact.friction.mu must be >= 0");
  require(c.friction.stick_velocity > 0 && c.friction.tanh_velocity > 0 && c.friction.slip_velocity > 0,
          "contact.friction velocities must be > 0");
  require(c.rank_tolerance > 0 && c.rank_tolerance < 1, "contact.rank_tolerance must be in (0, 1)");
  require(c.baumgarte_time > 0 && c.locate_tolerance > 0, "contact tolerances must be > 0");
  if (!model.effects.contact) return;
  require(!model.table.empty(), "contact needs a table (table: boxes)");
}

void check_motor(const Motor& m, int i, MotorModel model) {
  require(m.resistance > 0, at("motors", i) + ".resistance must be > 0");
  require(m.inductance >= 0, at("motors", i) + ".inductance must be >= 0");
  require(model != MotorModel::full || m.inductance > 0,
          at("motors", i) + ".inductance must be > 0 for the full motor model");
  require(m.gear_ratio > 0, at("motors", i) + ".gear_ratio must be > 0");
  require(m.voltage_limit > 0, at("motors", i) + ".voltage_limit must be > 0");
  require(m.current_limit > 0, at("motors", i) + ".current_limit must be > 0");
  require(m.rated_current > 0, at("motors", i) + ".rated_current must be > 0");
  require(m.efficiency > 0 && m.efficiency <= 1 && m.backdrive_efficiency > 0 &&
              m.backdrive_efficiency <= 1,
          at("motors", i) + ": gear efficiencies must be in (0, 1]");
  require(m.rotor_inertia >= 0 && m.gear_friction >= 0,
          at("motors", i) + ": rotor_inertia and gear_friction must be >= 0");
}

void check_sizes(const Model& model) {
  const auto n = static_cast<std::size_t>(model.dof);
  require(model.dof > 0, "dof must be > 0");
  require(model.joints.size() == n && model.links.size() == n, "joints/links must have dof entries");
  require(!model.has_motor() || model.motors.size() == n, "motors must have dof entries");
  require(model.damping.size() == 0 || model.damping.size() == model.dof,
          "damping must be empty or have dof entries");
  require(model.inputs.joints.empty() || model.inputs.joints.size() == n,
          "inputs must be empty or have dof entries");
  require(model.hand_link >= 0 && model.hand_link < model.dof, "hand_link out of range");
  require(model.options.step > 0 && model.options.duration > 0, "step and duration must be > 0");
}

// Merges a point mass at `point` (link frame) into a link: new com, and the
// inertia about it by the parallel-axis theorem.
void add_point_mass(Link& link, double mass, const Eigen::Vector3d& point) {
  const double m = link.mass + mass;
  const Eigen::Vector3d com = (link.mass * link.com + mass * point) / m;
  auto shift = [](const Eigen::Vector3d& d) {
    return Eigen::Matrix3d(d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  };
  link.inertia += link.mass * shift(link.com - com) + mass * shift(point - com);
  link.com = com;
  link.mass = m;
}

// The joint axes in the world at q = 0 (a rotation about one axis keeps the
// others parallel to it, so parallel at q = 0 means parallel everywhere).
Eigen::Vector3d planar_axis(const Model& model) {
  Eigen::Matrix3d R = model.base.rotation();
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  for (int i = 0; i < model.dof; ++i) {
    R = R * model.joints[i].origin_rotation;
    const Eigen::Vector3d a = R * model.joints[i].axis;
    if (i == 0) first = a;
    if (first.cross(a).norm() > 1e-12) return Eigen::Vector3d::Zero();
  }
  return first;
}

}  // namespace

void finalize(Model& model) {
  static std::atomic<long> next_id{1};
  model.id = next_id++;
  check_sizes(model);
  const int n = model.dof;
  for (int i = 0; i < n; ++i) {
    Joint& joint = model.joints[i];
    require(joint.axis.norm() > 0, at("joints", i) + ".axis must be non-zero");
    joint.axis.normalize();
    check_link(model.links[i], i);
    if (model.has_motor()) check_motor(model.motors[i], i, model.effects.motor);
  }
  check_contact_scene(model);
  require(model.hand_load.mass >= 0, "hand_load.mass must be >= 0");
  if (model.hand_load.mass != model.hand_mass_added) {  // once, however often finalize runs
    add_point_mass(model.links[model.hand_link], model.hand_load.mass - model.hand_mass_added,
                   model.hand_point);
    model.hand_mass_added = model.hand_load.mass;
  }
  require(!model.effects.friction || model.effects.contact, "friction needs contact");
  if (model.effects.joint_friction) {
    require(static_cast<int>(model.joint_friction.size()) == n,
            "joint_friction needs one entry per joint");
    for (const JointFriction& f : model.joint_friction)
      require(f.coulomb >= 0 && f.breakaway >= f.coulomb && f.stribeck_velocity > 0,
              "joint friction needs 0 <= coulomb <= breakaway and stribeck_velocity > 0");
  }
  for (const JointSpring& s : model.springs)
    require(s.joint >= 0 && s.joint < n && std::isfinite(s.torque) && std::isfinite(s.at) &&
                std::isfinite(s.stiffness) && s.stiffness >= 0,
            "a joint spring needs a joint of the arm, finite torque and angle, stiffness >= 0");
  if (model.damping.size() == 0) model.damping = Eigen::VectorXd::Zero(n);
  model.planar_axis = planar_axis(model);
  model.joint_rotations.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Joint& joint = model.joints[i];
    const Eigen::Vector3d& a = joint.axis;
    const Eigen::Matrix3d outer = a * a.transpose();
    Eigen::Matrix3d skew;
    skew << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
    JointRotation& r = model.joint_rotations[static_cast<std::size_t>(i)];
    r.fixed = joint.origin_rotation * outer;
    r.cosine = joint.origin_rotation * (Eigen::Matrix3d::Identity() - outer);
    r.sine = joint.origin_rotation * skew;
    r.axis = joint.origin_rotation * a;
  }

  // Reflected motor constants (docs/model.md, Motors): Km = K k, Jm = Im k^2, Dm = dm k^2.
  model.km = model.armature = model.resistance = model.inductance = model.voltage_limit =
      model.current_limit = Eigen::VectorXd::Zero(n);
  model.gear_efficiency = model.backdrive_efficiency = Eigen::VectorXd::Ones(n);
  model.gear_losses = false;
  model.viscous = model.effects.damping ? model.damping : Eigen::VectorXd::Zero(n);
  if (!model.has_motor()) return;
  for (int i = 0; i < n; ++i) {
    const Motor& m = model.motors[i];
    model.km[i] = m.km();
    model.armature[i] = model.effects.rotor_inertia ? m.jm() : 0.0;
    if (model.effects.damping) model.viscous[i] += m.dm();
    model.resistance[i] = m.resistance;
    model.inductance[i] = m.inductance;
    model.voltage_limit[i] = m.voltage_limit;
    model.current_limit[i] = m.current_limit;
    model.gear_efficiency[i] = m.efficiency;
    model.backdrive_efficiency[i] = m.backdrive_efficiency;
    model.gear_losses = model.gear_losses || m.efficiency < 1 || m.backdrive_efficiency < 1;
  }
}

}  // namespace elbowsim

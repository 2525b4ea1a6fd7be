#include "support/contact_scenes.hpp"

#include <cmath>
#include <memory>
#include <string>

#include "engine/contact/collision.hpp"
#include "engine/contact/friction.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "engine/run/derivative.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim::testing {

namespace {

InputProfile ramp(double value, double slope) {
  InputProfile p;
  p.kind = InputProfile::Kind::table;
  p.times = {0.0, 100.0};
  p.values = {value, value + 100.0 * slope};
  return p;
}

TableBox table_under(double top_z, double x) {
  TableBox box;
  box.size = Eigen::Vector3d(2.0, 1.0, 0.1);
  box.center = Eigen::Vector3d(x, 0, top_z - 0.05);
  return box;
}

}  // namespace

Model chain_with_elbows(int n, int p, std::uint32_t seed) {
  Model m = random_chain(n, seed);
  for (int k = 0; k < p; ++k)
    m.elbows.push_back({'e' + std::to_string(k), 1 + (k * 2) % (n - 1),
                        0.2 * Eigen::Vector3d::Random(), 0.03});
  m.table = {TableBox{}};
  m.effects.contact = true;
  finalize(m);
  return m;
}

void set_random_contacts(const Model& m, Data& data) {
  data.contact.active.clear();
  for (int k = 0; k < int(m.elbows.size()); ++k) {
    data.contact.active.push_back(k);
    data.contact.normal[k] = Eigen::Vector3d::Random().normalized();
    data.contact.surface[k] = Eigen::Vector3d::Random();
  }
}

void place(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
           double t) {
  const StateLayout s(model);
  if (!data.contact.world)
    data.contact.world = std::make_shared<CollisionWorld>(model, data.contact.geometry);
  data.x.setZero();
  data.x.segment(s.q(), s.n) = q;
  data.x.segment(s.qd(), s.n) = qd;
  data.t = t;
}

double ElbowArm::G1() const {
  return g * ((m1 * lc1 + m2 * l1) * std::cos(q1) + m2 * lc2 * std::cos(q1 + q2));
}
double ElbowArm::G2() const { return g * m2 * lc2 * std::cos(q1 + q2); }
double ElbowArm::statics_force(double tau1) const { return (G1() - tau1) / (l1 * std::cos(q1)); }

Model ElbowArm::model(double tau1_0, double slope) const {
  Model m = planar_arm({{l1, m1, lc1, 0.02}, {l2, m2, lc2, 0.01}});
  m.elbows = {Elbow{"elbow", 0, Eigen::Vector3d(l1, 0, 0), r}};
  m.table = {table_under(l1 * std::sin(q1) - r, l1)};
  m.effects.contact = true;
  m.initial.q = Eigen::Vector2d(q1, q2);
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints = {ramp(tau1_0, slope), ramp(G2(), 0.0)};
  m.options = {1.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

Model falling_arm(double lift, EventTiming events, double step, double restitution) {
  const ElbowArm arm;
  Model m = arm.model(0.0, 0.0);
  m.inputs.joints.clear();
  m.initial.q[0] += lift;
  m.contact.events = events;
  m.contact.restitution = restitution;
  m.contact.locate_tolerance = 1e-12;
  m.options = {0.6, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

Model sliding_arm(Stabilization stabilization, double duration, double step) {
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.3, 0.8, 0.15, 0.008}, {0.25, 0.5, 0.12, 0.004}});
  const double q1 = 0.5, q2 = -1.2;
  const double elbow_z = 0.3 * std::sin(q1) + 0.3 * std::sin(q1 + q2);
  m.elbows = {Elbow{"elbow", 1, Eigen::Vector3d(0.3, 0, 0), 0.03}};
  // The table's edge is in front of the shoulder, so only the elbow reaches it; the
  // links have no solid (as the scene's drift checks follow one sliding constraint):
  // after 5 s the sines tilt link 1 down onto the table.
  m.table = {table_under(elbow_z - 0.03, 0.85)};
  m.table[0].size.x() = 1.0;
  for (Link& link : m.links) link.collision.kind = LinkCollision::Kind::none;
  m.effects.contact = true;
  m.effects.stabilization = stabilization;
  // Quasi-static servos (back-EMF damping Km^2/R = 1.1 N m s/rad) holding 70 %
  // of the shoulder's and elbow's gravity torque and all of the wrist's, so
  // the elbow leans on the table, plus slow sines that make it slide.
  m.effects.motor = MotorModel::quasi_static;
  m.motors.assign(3, small_servo());
  m.initial.q = Eigen::Vector3d(q1, q2, 1.0);
  finalize(m);
  Data data(m);
  forward_kinematics(m, data, m.initial.q);
  Eigen::VectorXd gravity(3);
  inverse_dynamics(m, data, data.zero, data.zero, {false, true, false}, gravity);
  const Eigen::Vector3d share(0.7, 0.7, 1.0), amplitude(0.5, 0.4, 0.2), frequency(0.3, 0.45, 0.6);
  m.inputs.quantity = OpenLoopInputs::Quantity::voltage;
  m.inputs.joints.assign(3, InputProfile{});
  for (int j = 0; j < 3; ++j) {
    InputProfile& v = m.inputs.joints[j];
    v.kind = InputProfile::Kind::sine;
    v.offset = share[j] * gravity[j] * m.motors[j].resistance / m.motors[j].km();
    v.amplitude = amplitude[j];
    v.frequency = frequency[j];
  }
  m.options = {duration, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

Model SpinningRod::model(double duration) const {
  Model m;
  m.name = "spinning_rod";
  m.dof = 2;
  Joint yaw, pitch;
  yaw.axis = Eigen::Vector3d::UnitZ();
  pitch.axis = -Eigen::Vector3d::UnitY();
  Link hub, rod;
  hub.mass = 0.1;
  hub.inertia = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
  rod.mass = mass;
  rod.com = Eigen::Vector3d(length / 2, 0, 0);
  const double I = mass * length * length / 12;
  rod.inertia = Eigen::Vector3d(1e-5, I, I).asDiagonal();
  rod.tip = Eigen::Vector3d(length, 0, 0);
  m.joints = {yaw, pitch};
  // Only the tip sphere touches the table: the rod lies level at the table's
  // height, so its capsule would touch along its whole length.
  hub.collision.kind = rod.collision.kind = LinkCollision::Kind::none;
  m.links = {hub, rod};
  m.hand_link = 1;
  m.hand_point = rod.tip;
  m.elbows = {Elbow{"tip", 1, rod.tip, r}};
  m.table = {table_under(-r, 0.0)};
  m.table[0].size = Eigen::Vector3d(3, 3, 0.1);
  m.effects.motor = MotorModel::none;
  m.effects.damping = false;
  m.effects.contact = true;
  m.effects.friction = true;
  m.contact.friction.mu = mu;
  m.initial.q = Eigen::Vector2d(0, 0);
  m.initial.qd = Eigen::Vector2d(omega0, 0);
  m.options = {duration, 1e-4, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

double SpinningRod::normal_force() const { return mass * g * 0.5; }
double SpinningRod::yaw_inertia() const {
  return 1e-4 + mass * length * length / 12 + mass * (length / 2) * (length / 2);
}

Eigen::Vector3d PressedTip::tip() const {
  return Eigen::Vector3d(l1 * std::cos(q1) + l2 * std::cos(q1 + q2), 0,
                         l1 * std::sin(q1) + l2 * std::sin(q1 + q2));
}

Eigen::Vector2d PressedTip::torques(double ft, double force) const {
  Model m = planar_arm({{l1, m1, l1 / 2, 0.02}, {l2, m2, l2 / 2, 0.01}});
  Data data(m);
  forward_kinematics(m, data, Eigen::Vector2d(q1, q2));
  Matrix3Xd J(3, 2);
  point_jacobian(m, data, 1, Eigen::Vector3d(l2, 0, 0) - r * (data.rotation[1].transpose() * Eigen::Vector3d::UnitZ()), J);
  return -(J.transpose() * Eigen::Vector3d(ft, 0, force));
}

Model PressedTip::model(double ratio0, double slope, double duration, double step) const {
  Model m = planar_arm({{l1, m1, l1 / 2, 0.02}, {l2, m2, l2 / 2, 0.01}});
  m.gravity.setZero();
  m.elbows = {Elbow{"tip", 1, Eigen::Vector3d(l2, 0, 0), r}};
  m.table = {table_under(tip().z() - r, tip().x())};
  for (Link& link : m.links) link.collision.kind = LinkCollision::Kind::none;
  m.effects.contact = true;
  m.effects.friction = true;
  m.contact.friction.mu = mu;
  m.initial.q = Eigen::Vector2d(q1, q2);
  // The friction force is -ratio mu fn along x: the torques push toward +x.
  const Eigen::Vector2d at0 = torques(-ratio0 * mu * fn, fn);
  const Eigen::Vector2d rate = torques(-(ratio0 + 1) * mu * fn, fn) - at0;  // per unit ratio
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints = {ramp(at0[0], slope * rate[0]), ramp(at0[1], slope * rate[1])};
  m.options = {duration, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

void gravity_share_with_sines(Model& m, const Eigen::VectorXd& q, double share, double amplitude,
                              const std::vector<double>& frequency) {
  finalize(m);
  Data data(m);
  forward_kinematics(m, data, q);
  Eigen::VectorXd gravity(q.size());
  inverse_dynamics(m, data, data.zero, data.zero, {false, true, false}, gravity);
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints.assign(static_cast<std::size_t>(q.size()), InputProfile{});
  for (std::size_t j = 0; j < m.inputs.joints.size(); ++j) {
    InputProfile& tau = m.inputs.joints[j];
    tau.kind = InputProfile::Kind::sine;
    tau.offset = share * gravity[static_cast<Eigen::Index>(j)];
    tau.amplitude = amplitude;
    tau.frequency = frequency[j];
  }
}

Model two_point_arm(double share, double amplitude, double duration, double step) {
  Model m = planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.3, 0.8, 0.15, 0.008}, {0.3, 0.5, 0.15, 0.005}});
  const double q1 = 0.6, j1z = 0.3 * std::sin(q1), r = 0.02, z = -0.05;
  const double a2 = std::asin((z - j1z) / 0.3);  // link 1's angle: its end at height z
  const Eigen::Vector3d q(q1, a2 - q1, -a2);      // link 2 level
  m.elbows = {Elbow{"elbow", 1, Eigen::Vector3d(0.3, 0, 0), r}, Elbow{"tip", 2, Eigen::Vector3d(0.3, 0, 0), r}};
  m.table = {table_under(z - r, 0.5)};
  for (Link& link : m.links) link.collision.kind = LinkCollision::Kind::none;
  m.effects.contact = true;
  m.effects.friction = true;
  m.contact.friction.mu = 0.4;
  m.initial.q = q;
  gravity_share_with_sines(m, q, share, amplitude, {1.3, 2.1, 1.7});
  m.options = {duration, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

Eigen::Vector3d contact_force_from_dynamics(const Model& model, Data& data, int slot) {
  const StateLayout s(model);
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  const Eigen::VectorXd qd = data.x.segment(s.qd(), s.n);
  mass_matrix_crba(model, data);
  bias_torques(model, data, qd);
  const Eigen::VectorXd Q = data.mass_matrix * data.qdd + data.bias - data.actuation;
  const Primitive& p = data.contact.primitive_of(slot);
  const Eigen::Vector3d n = data.contact.normal[slot];
  Matrix3Xd J(3, model.dof);
  point_jacobian(model, data, p.link, contact_point_local(data, slot, n), J);
  return J.transpose().completeOrthogonalDecomposition().solve(Q);
}

double slip_speed_of(const Model& model, Data& data, int slot) {
  const StateLayout s(model);
  forward_kinematics(model, data, data.x.segment(s.q(), s.n));
  return tangential_velocity(data, slot, data.contact.normal[slot], data.x.segment(s.qd(), s.n)).norm();
}

}  // namespace elbowsim::testing

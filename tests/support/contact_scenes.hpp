// Scenes with elbows on a table, shared by the contact tests and benchmarks.
#pragma once

#include <vector>

#include "engine/data.hpp"
#include "support/models.hpp"

namespace elbowsim::testing {

// Random chain of n joints (random_chain) with p elbows on links 1, 3, ... (mod n - 1) at
// random points, one default table box, contact on.
Model chain_with_elbows(int n, int p, std::uint32_t seed);

// Every elbow of m active, with a random unit table normal and surface point (rows of M*
// without detection).
void set_random_contacts(const Model& m, Data& data);

// Puts the joint state (q, qd) at time t into data.x (its other components zero) and
// builds the collision world if data has none: the state the contact stages read
// (detect_contacts, select_active_set, ...) when a test calls them on their own.
void place(const Model& model, Data& data, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
           double t);

// 2-link planar arm leaning on an elbow sphere at the end of link 0 (on joint
// 1), table top exactly under it at q0; torque inputs (motor none).
//
//   z                 link 1
//   |              o--------- hand
//   |  link 0    / (elbow sphere, radius r, on the table)
//   o----------o
//   ===========================  table top
struct ElbowArm {
  double l1 = 0.4, l2 = 0.35, lc1 = 0.2, lc2 = 0.175, m1 = 1.3, m2 = 0.9, r = 0.03, g = 9.81;
  double q1 = -0.3, q2 = 0.6;
  // Gravity torques at rest (hand-derived, angles from +x toward +z).
  double G1() const;
  double G2() const;
  // The table force that balances shoulder torque tau1 (link 1 held by G2).
  double statics_force(double tau1) const;
  // Torque inputs tau1(t) = tau1_0 + slope t, tau2 = G2.
  Model model(double tau1_0, double slope) const;
};

// The ElbowArm released from `lift` rad (shoulder) above its resting pose, unactuated,
// with events located to 1e-12 s, the given event timing, step and restitution; 0.6 s.
Model falling_arm(double lift, EventTiming events, double step, double restitution);

// 3-link planar arm whose elbow (end of link 1) rests on the table and can
// slide along it; joint torques follow slow sines.
Model sliding_arm(Stabilization stabilization, double duration, double step);

// Rod on a yaw (z) and a pitch (-y) joint, horizontal, its tip sphere resting
// on a table below; spinning at omega0 about z. Friction mu.
struct SpinningRod {
  double length = 0.5, mass = 1.0, r = 0.02, omega0 = 2.0, mu = 0.3, g = 9.81;
  Model model(double duration) const;
  double normal_force() const;       // m g lc / l (lc = l/2)
  double yaw_inertia() const;        // about the z axis through the base
};

// 2-link planar arm (no gravity, no motors, links without solids) whose hand
// is a sphere ("tip", radius r, the hand point) resting on the table top at
// q0. The joint torques tau(t) = -Jp^T (f_x(t), fn) (Jp: the contact point's
// Jacobian at q0, x and z rows) make the table push the resting tip with the
// normal force fn and the tangential force f_x(t) = -ratio(t) mu fn, ratio =
// ratio0 + slope t: the torques push the tip toward +x with ratio(t) times
// what friction can hold.
//
//          o
//  link 0 / \ link 1
//        o   O tip
//   ============== table top
struct PressedTip {
  double l1 = 0.4, l2 = 0.35, m1 = 1.0, m2 = 0.8, r = 0.02, q1 = 0.9, q2 = -1.8;
  double mu = 0.5, fn = 10.0;
  Model model(double ratio0, double slope, double duration, double step) const;
  Eigen::Vector3d tip() const;                           // the sphere's centre at q0 [m]
  Eigen::Vector2d torques(double ft, double fn) const;   // [N m] for the table force (ft, fn) at q0
};

// Joint torque inputs for m at pose q: `share` of the gravity torques there
// plus sines of `amplitude` [N m] at frequency[j] [Hz] (one per joint).
void gravity_share_with_sines(Model& m, const Eigen::VectorXd& q, double share, double amplitude,
                              const std::vector<double>& frequency);

// 3-link planar arm (gravity, no motors, links without solids) lying on two
// spheres, "elbow" at the end of link 1 and "tip" at the end of link 2 (link 2
// level), mu 0.4; joint torques: `share` of the gravity torques at q0 plus
// sines of `amplitude` [N m] that make the contacts stick and slip.
Model two_point_arm(double share, double amplitude, double duration, double step);

// The table's force on the arm at the contact point of `slot`, from the
// dynamics at the state in data.x: Q = (M + Jm) qdd + B - tau = Jp^T f, solved
// for f in the least-squares sense (exact when Jp has full column rank).
Eigen::Vector3d contact_force_from_dynamics(const Model& model, Data& data, int slot);

// Speed of slot k's contact point across the table normal [m/s] at the state in data.x.
double slip_speed_of(const Model& model, Data& data, int slot);

}  // namespace elbowsim::testing

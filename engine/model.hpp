// The immutable description of a robot and the effects a scene simulates.
// Built once from a scenario (see app/scenario), never changed during a run;
// everything that changes per run lives in Data (data.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "inputs.hpp"

namespace elbowsim {

enum class MotorModel { none, quasi_static, full };
enum class IntegratorKind { euler, semi_implicit_euler, rk4 };
enum class DynamicsMethod { walker_orin, crba, aba };

const char* to_string(MotorModel m);
const char* to_string(IntegratorKind k);
const char* to_string(DynamicsMethod d);

// Which physical effects the scene simulates (DESIGN.md §3). An effect that is
// off costs nothing: its terms are skipped, not multiplied by zero.
struct Effects {
  bool gravity = true;        // G(q)
  bool damping = true;        // (D + Dm) qd
  MotorModel motor = MotorModel::full;
  bool rotor_inertia = true;  // Jm added to M (only with a motor)
};

// Revolute joint i: the frame of link i is the frame of link i-1 (or the base)
// moved by the fixed origin transform, then rotated by q_i about `axis`.
struct Joint {
  Eigen::Matrix3d origin_rotation = Eigen::Matrix3d::Identity();  // in parent link frame
  Eigen::Vector3d origin_position = Eigen::Vector3d::Zero();      // [m], in parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();                // unit, in this link's frame
};

// Rigid link carried by joint i. All vectors are in the link's own frame.
struct Link {
  double mass = 1.0;                                       // [kg] > 0
  Eigen::Vector3d com = Eigen::Vector3d::Zero();           // [m] centre of mass
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();   // [kg m^2] about the com
  double radius = 0.02;                                    // [m] drawing/collision capsule
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();           // [m] far end of the link
};

// DC servo of one joint (DESIGN.md §1, paper eq. 16-27). Reflected to the joint
// through the gear ratio k: Km = K k, Jm = Im k^2, Dm = dm k^2.
struct Motor {
  double resistance = 1.0;         // R [ohm] > 0
  double inductance = 1e-3;        // L [H] >= 0 (> 0 for the full model)
  double torque_constant = 0.05;   // K = K_T = K_E [N m / A]
  double gear_ratio = 1.0;         // k [-] > 0
  double rotor_inertia = 0.0;      // Im [kg m^2] >= 0, motor side
  double gear_friction = 0.0;      // dm [N m s / rad] >= 0, motor side
  double voltage_limit = 24.0;     // [V] > 0, |v| is clamped to it

  double km() const { return torque_constant * gear_ratio; }
  double jm() const { return rotor_inertia * gear_ratio * gear_ratio; }
  double dm() const { return gear_friction * gear_ratio * gear_ratio; }
};

struct Options {
  double duration = 1.0;  // [s]
  double step = 1e-3;     // [s] fixed integration step
  IntegratorKind integrator = IntegratorKind::rk4;
  DynamicsMethod dynamics = DynamicsMethod::crba;
};

struct Model {
  std::string name;
  int dof = 0;  // s, number of revolute joints = number of links

  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();  // world pose of the base frame
  std::vector<Joint> joints;  // [dof]
  std::vector<Link> links;    // [dof]
  std::vector<Motor> motors;  // [dof], used when effects.motor != none
  Eigen::VectorXd damping;    // D, joint viscous damping [N m s / rad], [dof]
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  // [m/s^2], world

  // The hand: a point on a link (default: the tip of the last link).
  int hand_link = 0;
  Eigen::Vector3d hand_point = Eigen::Vector3d::Zero();

  // Initial state [dof each]; empty vectors mean zeros.
  struct InitialState {
    Eigen::VectorXd q, qd, current;
  } initial;

  Effects effects;
  Options options;
  OpenLoopInputs inputs;  // voltages (motor on) or torques (motor none)

  // Derived by finalize(): reflected motor constants, per joint [dof].
  Eigen::VectorXd km;             // Km [N m / A]
  Eigen::VectorXd armature;       // Jm [kg m^2] (zero when rotor_inertia is off)
  Eigen::VectorXd viscous;        // D + Dm [N m s / rad] (zero when damping is off)
  Eigen::VectorXd resistance;     // R [ohm]
  Eigen::VectorXd inductance;     // L [H]
  Eigen::VectorXd voltage_limit;  // [V]

  bool has_motor() const { return effects.motor != MotorModel::none; }
  bool has_current_state() const { return effects.motor == MotorModel::full; }
  bool has_armature() const { return has_motor() && effects.rotor_inertia; }
  // The names of the active effects, for summaries ("gravity", "motor:full", ...).
  std::vector<std::string> active_effects() const;
};

// Checks the model's invariants and fills its derived members. Throws
// std::invalid_argument naming the offending member. The scenario loader
// reports the same problems earlier, with file and line; this is the backstop
// for models built in code (tests, benchmarks).
void finalize(Model& model);

}  // namespace elbowsim

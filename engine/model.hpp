// The immutable description of a robot and the effects a scene simulates.
// Built once from a scenario (see app/scenario), never changed during a run;
// everything that changes per run lives in Data (data.hpp).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <Eigen/Geometry>
#include <string>
#include <utility>
#include <vector>

#include "engine/control/inputs.hpp"

namespace elbowsim {

enum class MotorModel { none, quasi_static, full };
// Fixed step: euler, semi_implicit_euler, rk4 (exponential in the currents' -R/L).
// Adaptive, with error control and dense output: dopri5 (explicit, order 5(4)),
// ros34pw2 (linearly implicit Rosenbrock-W, order 3(2), for stiff electrics).
enum class IntegratorKind { euler, semi_implicit_euler, rk4, dopri5, ros34pw2 };
bool is_adaptive(IntegratorKind k);
enum class DynamicsMethod { walker_orin, crba, aba };
enum class Stabilization { none, baumgarte, projection };
enum class EventTiming { step, locate };
// How the constrained step's saddle-point system is solved (contact/constrained_dynamics.hpp);
// automatic: aba from kAbaCrossover joints on, schur below.
enum class ConstraintSolver { automatic, schur, aba, dense_lu, explicit_inverse };
enum class FrictionLaw { coulomb, tanh, saturated };

const char* to_string(MotorModel m);
const char* to_string(IntegratorKind k);
const char* to_string(DynamicsMethod d);
const char* to_string(Stabilization s);
const char* to_string(EventTiming e);
const char* to_string(ConstraintSolver s);
const char* to_string(FrictionLaw law);

// Which physical effects the scene simulates (docs/model.md, Effects). An effect that is
// off costs nothing: its terms are skipped, not multiplied by zero.
struct Effects {
  bool gravity = true;        // G(q)
  bool damping = true;        // (D + Dm) qd
  MotorModel motor = MotorModel::full;
  bool rotor_inertia = true;  // Jm added to M (only with a motor)
  bool contact = false;       // elbows on the table: Bullet detection, rows of M*
  bool friction = false;      // friction at resting contacts (contact.friction: law and mu)
  bool impacts = true;        // touchdown applies an impulse (restitution e)
  bool joint_friction = false;  // Coulomb and Stribeck friction at the joints, with sticking
  Stabilization stabilization = Stabilization::baumgarte;  // drift control of C(q) = 0
};

// A compliant pad on an elbow (docs/model.md, Compliant pad): a Kelvin-Voigt
// layer, massless, whose outer surface is the elbow sphere's. Pressed d deep
// (d = -distance > 0) at rate d' it pushes back f = k d + c d' along the
// table's normal while f > 0; it never pulls (the contact releases where f
// reaches 0, and the elastic energy still in it, k d^2 / 2, is lost there).
// No impulse at landing: the force is finite. Friction stays Coulomb, with
// exact sticking, bounded by this f. Stiffness 0: no pad (the rigid contact).
struct Pad {
  double stiffness = 0;     // k [N/m] > 0 for a pad
  double damping = 0;       // c [N s/m] >= 0
  double thickness = 0.005; // [m] > 0: pressed deeper, the pad bottoms out (the run is invalid)
  bool on() const { return stiffness > 0; }
};

// An elbow point: a sphere on a link that can rest on the table.
struct Elbow {
  Elbow() = default;
  // A rigid elbow unless `pad` is given (the constructor keeps code that
  // builds elbows from their first four members as it was).
  Elbow(std::string name_, int link_, const Eigen::Vector3d& point_, double radius_, Pad pad_ = {})
      : name(std::move(name_)), link(link_), point(point_), radius(radius_), pad(pad_) {}

  std::string name;                                // for events and messages
  int link = 0;                                    // carrying link, 0-based
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); // [m] sphere centre, link frame
  double radius = 0.03;                            // [m] > 0 (with a pad: to its outer surface)
  Pad pad;                                         // compliant pad (off by default: rigid)
};

// One solid box of the table (several make steps or gaps).
struct TableBox {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();         // [m] world
  Eigen::Vector3d size = Eigen::Vector3d(1.0, 1.0, 0.05);   // [m] full edge lengths, > 0
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();   // box frame -> world
};

// Friction at resting contacts (effects.friction); docs/model.md, Friction.
//   coulomb    exact Coulomb friction: a contact sticks while its tangential
//              force stays inside the cone |f_t| <= mu f_n, else slides with
//              |f_t| = mu f_n against its slip; stick and slip are decided by a
//              complementarity problem with the normal forces, and their
//              changes are located like landings (contact/friction.hpp);
//   tanh       f_t = -mu f_n tanh(|v_t| / tanh_velocity) v_t / |v_t|;
//   saturated  f_t = -mu f_n v_t / max(|v_t|, slip_velocity).
// The regularised laws never stick: a pressed contact creeps at a speed that
// grows with the regularisation velocity.
struct FrictionOptions {
  FrictionLaw law = FrictionLaw::coulomb;
  double mu = 0.0;               // [-] >= 0
  // [m/s] coulomb: a contact point slower than this may stick (a slip that
  // stops is located to locate_tolerance, leaving ~1e-8 m/s; faster slips slide on).
  double stick_velocity = 1e-6;
  double tanh_velocity = 1e-3;   // [m/s] tanh: the speed at which f_t reaches 76 % of mu f_n
  double slip_velocity = 1e-4;   // [m/s] saturated: below it f_t falls linearly to 0
};

// Contact parameters and numerical tolerances (used when effects.contact).
struct ContactOptions {
  double restitution = 0.0;   // e in [0, 1], normal impacts
  FrictionOptions friction;   // used when effects.friction
  // locate: a landing is found where it happens, not up to speed x step deep at the
  // end of the step (2 mm at 2 m/s and 1 ms: beyond penetration_tolerance).
  EventTiming events = EventTiming::locate;
  double locate_tolerance = 1e-9;      // [s] event-time tolerance (events: locate)
  ConstraintSolver solver = ConstraintSolver::automatic;  // of the constrained step (same answers; cost differs)
  double touch_distance = 1e-6;        // [m] signed distance that counts as touching
  double separation_velocity = 1e-6;   // [m/s] normal speed above which a contact separates
  // [m/s] a landing whose rebound would be slower than this is plastic: it settles
  // (restitution < 1 makes bounces accumulate in finite time, Zeno). < 0: the
  // default, |gravity| x simulation.step (settle_speed() in contact/impact.hpp).
  double settle_speed = -1.0;
  double baumgarte_time = 0.01;        // [s] Baumgarte time constant T: alpha = 2/T, beta = 1/T^2
  double rank_tolerance = 1e-9;        // relative pivot threshold for dependent rows
  double initial_penetration = 1e-4;   // [m] an elbow deeper at t = 0 is a scenario error
  // [m] a link or an elbow deeper than this in a table box makes the run invalid, with
  // contact on or off (run/validity.hpp). 1 mm: far above the drift of resting contacts
  // (1e-12 m) and a step's overshoot at landing (~0.2 mm at 0.2 m/s and 1 ms).
  double penetration_tolerance = 1e-3;
  // [m] the broad phase's reach: a primitive this close to a box's bounds gets its exact
  // distance (closed form); farther ones cost nothing. 1 cm covers a landing at 10 m/s
  // within a 1 ms step.
  double detection_margin = 0.01;
  // Most contact rows at once (workspaces are sized for them when the run starts); 0: the
  // number of slots, at most 2 dof + elbows + 4 (rows beyond dof are dependent anyway).
  int max_rows = 0;
};

// When a run's numbers can be trusted (run/validity.hpp). A run that breaks a
// bound stops with exit 3 and a message naming the check, the time, the
// quantity and the likely cause; its report shows the failure first.
struct ValidityOptions {
  // |energy-balance residual| <= energy_residual x the energy that flowed (in
  // and out, each counted once, so regeneration cannot hide an error). RK4 at
  // the shipped steps closes to ~1e-8; 1e-3 flags an integration error of 0.1 %.
  double energy_residual = 1e-3;
  // |i_j| <= current_factor x V_max / R_j (the stall current at the voltage limit;
  // back-driven motors can exceed it a little, a diverging run by orders).
  double current_factor = 10;
  // |qd_j| <= speed_factor x V_max / Km_j (the free-running speed at the limit).
  double speed_factor = 10;
  // An elbow the task keeps on the table rests for at least this share of the run.
  double rest_share = 0.9;
};

// When a valid run warns (run/warnings.hpp): what a user needs to know about
// what the run did, printed on stderr, in summary.json and first in the report.
struct WarningOptions {
  // A motor held at its voltage or current limit for more than this share of
  // the run: it cannot give what it is asked, and the arm follows the limit.
  // 5 %: brief peaks at a task's start and end are normal, a tenth is not.
  double saturation_share = 0.05;
  // [m] the hand farther than this from its desired point at some sample (a
  // task): 1 mm, a visible miss for a hand writing or placing on a table.
  double hand_error = 1e-3;
  // A body the scene does not plan to rest on the table (a link's own solid,
  // or an elbow the task holds above it) resting for more than this share of
  // the run: the arm leans on something no result accounts for. 1 %: a brief
  // graze passes, a forearm lying on the table for a tenth of the run does not.
  double unplanned_contact_share = 0.01;
};

// Revolute joint i: the frame of link i is the frame of link i-1 (or the base)
// moved by the fixed origin transform, then rotated by q_i about `axis`.
struct Joint {
  Eigen::Matrix3d origin_rotation = Eigen::Matrix3d::Identity();  // in parent link frame
  Eigen::Vector3d origin_position = Eigen::Vector3d::Zero();      // [m], in parent link frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();                // unit, in this link's frame
};

// A joint's rotation in its parent's frame by Rodrigues' formula, split by
// finalize() so that forward kinematics costs one sin, one cos and 18
// multiply-adds per joint: with O = origin_rotation and the unit axis a,
//   O R(a, q) = O a a^T + cos q O (1 - a a^T) + sin q O [a]x.
struct JointRotation {
  Eigen::Matrix3d fixed, cosine, sine;  // O a a^T, O (1 - a a^T), O [a]x
  Eigen::Vector3d axis;                 // O a: the axis in the parent frame
};

// Rigid link carried by joint i. All vectors are in the link's own frame.
// The solid a link has against the table (link frame). Default: the capsule
// from the link frame's origin to its tip with the link's radius.
struct LinkCollision {
  enum class Kind { capsule, sphere, box, none };
  Kind kind = Kind::capsule;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // [m] sphere or box centre
  // [m] sphere radius; capsule: 0 (the default) is the link's capsule from its
  // origin to its tip, > 0 the capsule from `from` to `to` (a URDF cylinder's)
  double radius = 0;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();     // [m] box edge lengths (axes of the link frame)
  Eigen::Vector3d from = Eigen::Vector3d::Zero();     // [m] capsule ends (radius > 0)
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
};

struct Link {
  double mass = 1.0;                                       // [kg] > 0
  Eigen::Vector3d com = Eigen::Vector3d::Zero();           // [m] centre of mass
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();   // [kg m^2] about the com
  double radius = 0.02;                                    // [m] drawing/collision capsule
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();           // [m] far end of the link
  LinkCollision collision;                                 // its solid against the table
};

// DC servo of one joint (docs/model.md, Motors; paper eq. 16-27). Reflected to the joint
// through the gear ratio k: Km = K k, Jm = Im k^2, Dm = dm k^2. The defaults are the
// built-in servo of scenario files (scenarios/README.md, motors): a 24 V brushed DC
// motor of the 20 W class behind 100:1, lossless gear; kBuiltinRatedCurrent its rating.
struct Motor {
  double resistance = 2.0;         // R [ohm] > 0
  double inductance = 0.5e-3;      // L [H] >= 0 (> 0 for the full model)
  double torque_constant = 0.03;   // K = K_T = K_E [N m / A]
  double gear_ratio = 100.0;       // k [-] > 0
  double rotor_inertia = 5e-7;     // Im [kg m^2] >= 0, motor side
  double gear_friction = 0.0;      // dm [N m s / rad] >= 0, motor side
  double voltage_limit = 24.0;     // [V] > 0, |v| is clamped to it
  // [A] > 0: the amplifier keeps |i| within it by narrowing the voltage to
  // back-EMF +- R current_limit (motor.cpp); infinity: no limit.
  double current_limit = std::numeric_limits<double>::infinity();
  // [A] > 0: continuous (thermal) rating. Not a limit: a run whose RMS
  // current exceeds it warns (the motor would overheat); infinity: unrated.
  double rated_current = std::numeric_limits<double>::infinity();
  // (0, 1]: the gear's efficiency when the motor drives the load (joint
  // torque = efficiency x Km i) and when the load drives the motor (joint
  // torque = Km i / backdrive_efficiency). 1, 1: a lossless gear.
  double efficiency = 1.0;
  double backdrive_efficiency = 1.0;
  // The scenario gave none of this joint's motor constants (resistance,
  // inductance, torque_constant, gear_ratio, rotor_inertia): it runs the
  // built-in servo, rated kBuiltinRatedCurrent unless rated_current says
  // otherwise. Messages say so; the physics does not read it.
  bool builtin = false;

  double km() const { return torque_constant * gear_ratio; }
  double jm() const { return rotor_inertia * gear_ratio * gear_ratio; }
  double dm() const { return gear_friction * gear_ratio * gear_ratio; }
};

// [A] the built-in servo's continuous rating (Motor::builtin): the 20 W class.
inline constexpr double kBuiltinRatedCurrent = 1.0;

// Dry friction at a joint, on its output side (docs/model.md, Joint friction):
// sliding at speed w it resists with tau(w) = coulomb + (breakaway - coulomb)
// exp(-(w / stribeck_velocity)^2); stuck, it holds up to breakaway.
struct JointFriction {
  double coulomb = 0.0;            // [N m] >= 0, the sliding friction torque at speed
  double breakaway = 0.0;          // [N m] >= coulomb, the most a stuck joint holds
  double stribeck_velocity = 0.01; // [rad/s] > 0, how fast the breakaway excess fades
};

// A torsion spring at a joint, a counterbalance: the torque it exerts on the
// joint is torque - stiffness (q - at), conservative (potential
// -torque (q - at) + stiffness (q - at)^2 / 2; docs/model.md, "Joint springs").
// stiffness 0 is a constant-torque spring (a cam or constant-force balancer).
struct JointSpring {
  int joint = 0;
  double torque = 0.0;     // [N m] exerted at q = at, positive along the joint's axis
  double stiffness = 0.0;  // [N m/rad] >= 0
  double at = 0.0;         // [rad]
};

// Constant load at the hand: a point mass carried at the hand point and/or a
// constant world force on it (e.g. pressing a pen).
struct HandLoad {
  double mass = 0.0;                                  // [kg] >= 0
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // [N] world
};

struct Options {
  double duration = 1.0;  // [s]
  double step = 1e-3;     // [s] fixed integration step; adaptive: the first step and the recording interval
  IntegratorKind integrator = IntegratorKind::rk4;
  DynamicsMethod dynamics = DynamicsMethod::crba;
  // Adaptive integrators: a step is accepted when its error estimate e meets
  // sqrt(mean((e_k / (atol + rtol max(|x_k|, |x_k+|)))^2)) <= 1 (Hairer's norm).
  double rtol = 1e-6;
  double atol = 1e-9;
  double max_step = 0;  // [s] longest adaptive step; 0: step with contact (landings are checked at step ends), else duration / 10
  // Why `integrator` was chosen when the scenario left it to auto
  // (run/integrator_choice.hpp); empty when the scenario named it.
  std::string integrator_reason = "";
};

struct Model {
  std::string name;
  long id = 0;  // a fresh number from every finalize(): Data remembers it (check_data)
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

  // Elbows and table (used when effects.contact).
  std::vector<Elbow> elbows;
  std::vector<TableBox> table;
  ContactOptions contact;
  ValidityOptions validity;
  WarningOptions warn;

  Effects effects;
  Options options;
  OpenLoopInputs inputs;  // voltages (motor on) or torques (motor none)

  // A payload at the hand (part of the plant; the experiment's task and
  // controller live beside the model, control/experiment.hpp).
  HandLoad hand_load;
  std::vector<JointFriction> joint_friction;  // [n] with effects.joint_friction
  std::vector<JointSpring> springs;           // none: no springs (any number per joint)
  double hand_mass_added = 0;  // [kg] of hand_load.mass already merged into the hand link by finalize()

  // Derived by finalize(): reflected motor constants, per joint [dof].
  Eigen::VectorXd km;             // Km [N m / A]
  Eigen::VectorXd armature;       // Jm [kg m^2] (zero when rotor_inertia is off)
  Eigen::VectorXd viscous;        // D + Dm [N m s / rad] (zero when damping is off)
  Eigen::VectorXd resistance;     // R [ohm]
  Eigen::VectorXd inductance;     // L [H]
  Eigen::VectorXd voltage_limit;  // [V]
  Eigen::VectorXd current_limit;  // [A] (infinity: none)
  Eigen::VectorXd gear_efficiency, backdrive_efficiency;  // [-] per joint
  bool gear_losses = false;       // a gear efficiency below 1 (E_gear in the balance)
  // The common world direction of every joint axis when they are all parallel
  // (a planar arm: every point moves in a plane normal to it, so a contact
  // whose normal lies in that plane has one tangent direction); zero otherwise.
  Eigen::Vector3d planar_axis = Eigen::Vector3d::Zero();
  std::vector<JointRotation> joint_rotations;  // [n] (kinematics.cpp)

  // Coulomb friction with stick and slip (effects.friction, law coulomb, mu > 0).
  bool has_coulomb_friction() const {
    return effects.friction && contact.friction.law == FrictionLaw::coulomb && contact.friction.mu > 0;
  }

  // Some elbow has a compliant pad (and contact is on).
  bool has_pads() const;
  bool has_springs() const { return !springs.empty(); }

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

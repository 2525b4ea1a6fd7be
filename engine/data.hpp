// Per-run data: state, stage outputs and scratch, sized once from a Model so
// that a simulation step allocates nothing. Every vector below is in world
// coordinates unless it says otherwise; [n] is the model's dof.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/contact/contact_data.hpp"
#include "engine/control/digital_loop.hpp"
#include "engine/eigen_types.hpp"
#include "engine/recording/energy_terms.hpp"
#include "engine/model.hpp"
#include "engine/run/step_log.hpp"

namespace elbowsim {

struct Controller;

// What the validity checks follow over a run (run/validity.hpp).
struct ValidityTrack {
  double max_held = 0;                  // [J] most energy the arm held at a recorded sample
  double first_exceeded = std::nan("");  // [s] when the balance residual first passed its bound
};

struct Data {
  explicit Data(const Model& model);

  // --- the model it was made for (check_data) -------------------------------
  long model_id = 0;        // Model::id at construction
  int dof = 0;              // [n]
  int state_size = 0;       // size of x (state_layout.hpp)

  // --- state -------------------------------------------------------------
  double t = 0;             // [s]
  Eigen::VectorXd q;        // [n] joint angles [rad]
  Eigen::VectorXd qd;       // [n] joint rates [rad/s]
  Eigen::VectorXd current;  // [n] motor currents [A] (state only for motor: full)

  // --- stage outputs of the last derivative evaluation --------------------
  Eigen::VectorXd qdd;           // [n] joint accelerations [rad/s^2]
  Eigen::VectorXd voltage;       // [n] applied (saturated) motor voltage [V]
  Eigen::VectorXd current_rate;  // [n] di/dt [A/s] (motor: full)
  Eigen::VectorXd actuation;     // [n] Km i through the gear (efficiency), or the input torque without motors [N m]
  double gear_loss_power = 0;    // [W] (Km i - actuation) . qd: what the gears keep (gear efficiency)

  // --- kinematics (forward_kinematics) ------------------------------------
  std::vector<Eigen::Matrix3d> rotation;  // [n] link frame -> world
  std::vector<Eigen::Vector3d> origin;    // [n] joint i position = link frame origin [m]
  std::vector<Eigen::Vector3d> axis;      // [n] joint axis, unit
  std::vector<Eigen::Vector3d> com;       // [n] link centre of mass [m]
  std::vector<Eigen::Matrix3d> inertia;   // [n] link inertia about its com [kg m^2]
  // The q [n] and model id the kinematics above were computed for: a call at
  // the same q (bit for bit) reuses them (an RK stage at the step's start, the
  // detection that starts a step where the last one ended). NaN: none yet;
  // kinematics_model = 0 forces the next call to compute (benchmarks).
  Eigen::VectorXd kinematics_q;
  long kinematics_model = 0;
  long kinematics_serial = 0;  // counts the recomputations: a stamp for what is derived from them

  // --- dynamics scratch ----------------------------------------------------
  Eigen::MatrixXd mass_matrix;     // [n x n] M (+ Jm when rotor inertia is on)
  Eigen::VectorXd bias;            // [n] h + g + (D + Dm) qd
  Eigen::VectorXd tau;             // [n] scratch torque vector
  Eigen::VectorXd zero;            // [n] zeros, for calls that need "no qd/qdd"
  Eigen::VectorXd unit;            // [n] scratch unit vector (Walker-Orin columns)
  Eigen::LLT<Eigen::MatrixXd> llt;  // Cholesky of mass_matrix

  // Newton-Euler recursion, per link [n]
  std::vector<Eigen::Vector3d> omega, omega_dot, origin_acc, force, moment;
  // When bias_torques() left them (qdd = 0; origin_acc with gravity as -g):
  // the kinematics_serial and the rates qd they are for, so that the contact
  // rows can read each link's rates instead of sweeping again; -1: not.
  long bias_rates_serial = -1;
  Eigen::VectorXd bias_rates_qd;  // [n]
  // Spatial (Plucker, world origin) quantities of CRBA/ABA, per link [n]
  std::vector<Matrix6d> spatial_inertia, articulated_inertia;
  std::vector<Vector6d> motion_subspace, velocity, bias_acc, bias_force, acc, U;
  Eigen::VectorXd D, u;  // [n] ABA joint-space scratch
  // U_i / D_i and 1 / D_i (ABA's inward pass): the response sweeps multiply
  // where they would divide, which takes a division off their serial chain.
  std::vector<Vector6d> U_over_D;
  Eigen::VectorXd D_inv;
  // e_i = S_i^T U_{i+1} / D_{i+1} (0 for the last joint): the coupling of each
  // joint to its child, which the response sweeps split off their chains.
  Eigen::VectorXd coupling;

  // --- integrator state ----------------------------------------------------
  // x = [q; qd; i (motor: full); energy integrals] (state_layout.hpp)
  Eigen::VectorXd x, x_start, k1, k2, k3, k4, x_a, x_b, x_c;
  Eigen::ArrayXd lambda;  // stiff linear rates per component of x (derivative.hpp)
  // Exponential-integrator coefficients for one step length h (integrator.cpp):
  // `etd_full` for the scene's step, `etd_short` for shortened steps (events, the end).
  struct EtdCoefficients {
    double h = 0;
    Eigen::ArrayXd exp_h, exp_half, phi1_half, phi1_h, f1, f2, f3;
  } etd_full, etd_short;
  // Adaptive integrators (run/adaptive.hpp): the step the error control
  // proposes next, and what the last accepted step leaves for dense output.
  struct AdaptiveState {
    double h_next = 0;          // [s] proposed next step; 0: none yet (the first step tries options.step)
    double h_last = 0;          // [s] the last accepted step (before an event shortened it)
    double error_last = 1e-4;   // its error norm, for the PI control (1e-4: Hairer's start)
    // dopri5's stiffness test (adaptive.hpp): h |lambda| of the last accepted
    // step as its last two stages estimate it, the accepted steps in a row above
    // its stability edge and below it, and whether the run has said so.
    double stiffness = 0;
    int stiff_in_a_row = 0, nonstiff_in_a_row = 0;
    bool stiffness_warned = false;
    Eigen::VectorXd k5, k6, k7, f0, dfdt, error, x_saved;
    Eigen::MatrixXd dense;      // [size x 5] dopri5's continuous extension of the last step
    Eigen::MatrixXd jacobian;   // [size x size] df/dx at the last step's start (ros34pw2)
    Eigen::MatrixXd w;          // I - h gamma J (ros34pw2)
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;  // of w
  } adaptive;
  // What the integration cost: every derivative evaluation (recording and
  // event location included), and the adaptive integrators' rejected steps,
  // Jacobians and factorisations.
  struct IntegratorWork {
    long evaluations = 0, rejected = 0, jacobians = 0, factorisations = 0;
  } work;

  ContactData contact;

  // --- task and controller ---------------------------------------------------
  std::shared_ptr<const Controller> controller;  // tracking controller and its plan; null: open loop
  Eigen::VectorXd q_desired, qd_desired, v_feedforward;  // [n] the plan at the stage time
  DigitalLoopState loop;  // sampled control: measurements, estimate, held voltage (digital_loop.hpp)

  // --- joint friction (effects.joint_friction; dynamics/joint_friction.hpp) ---
  std::vector<signed char> joint_mode;  // [n] +1 / -1 sliding that way, 0 stuck (for the step)
  Eigen::VectorXd joint_friction_torque;  // [n] friction torque on each joint [N m] (stuck: what it holds)
  Eigen::VectorXd tau_applied;            // [n] actuation + friction [N m]
  Eigen::MatrixXd joint_mass;             // [n x n] M with the stuck joints locked (scratch)

  // Recorded rows fall at multiples of this [s] (simulate() sets it; 0: none):
  // fixed steps end on them, so a step grid shifted by a located event
  // realigns there (run/step.cpp).
  double record_interval = 0;

  EnergyTerms energy;           // at time t
  EnergyTerms energy_initial;   // at t = 0
  long step_count = 0;      // steps taken since reset()

  // --- what the last step reported, and why the run must stop --------------
  StepLog log;
  Failure failure;
  ValidityTrack validity;  // run/validity.hpp: what the checks follow over the run
};

// Throws std::invalid_argument when `data` was not made for `model` (another
// model id, dof, state size or number of elbows), naming what differs. step()
// and reset() call it always (it is a few comparisons); the algorithms call it
// in debug builds (ELBOWSIM_CHECK_DATA).
void check_data(const Model& model, const Data& data);

#ifndef NDEBUG
#define ELBOWSIM_CHECK_DATA(model, data) ::elbowsim::check_data(model, data)
#else
#define ELBOWSIM_CHECK_DATA(model, data) ((void)0)
#endif

}  // namespace elbowsim

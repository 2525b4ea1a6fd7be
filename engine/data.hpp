// Per-run data: state, stage outputs and scratch, sized once from a Model so
// that a simulation step allocates nothing. Every vector below is in world
// coordinates unless it says otherwise; [n] is the model's dof.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/model.hpp"

namespace elbowsim {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix3Xd = Eigen::Matrix<double, 3, Eigen::Dynamic>;
// Read-only view of a vector or of a segment of one, without copying.
using ConstVec = Eigen::Ref<const Eigen::VectorXd>;

// Energy terms of the balance E_in - losses = change of stored energy.
struct EnergyTerms {
  double electrical_in = 0;    // [J] integral of v.i (or tau.qd without motors)
  double joule = 0;            // [J] integral of i^T R i
  double viscous = 0;          // [J] integral of qd^T (D + Dm) qd
  double kinetic_links = 0;    // [J] 1/2 sum m v_c^2 + w^T I w
  double kinetic_rotors = 0;   // [J] 1/2 qd^T Jm qd
  double potential = 0;        // [J] -sum m g.c
  double magnetic = 0;         // [J] 1/2 i^T L i (full motor model only)
  // With contact:
  double friction = 0;         // [J] integral of mu fn |v_slide| (energy lost to sliding)
  double normal_work = 0;      // [J] integral of fn^T Jc qd, work of the table's push (0 if C holds)
  double impact_loss = 0;      // [J] kinetic energy lost in impacts
  double projection = 0;       // [J] stored-energy change made by drift projection
  double external = 0;         // [J] work of the constant hand force
  double mechanical() const { return kinetic_links + kinetic_rotors + potential; }
  double stored() const { return mechanical() + magnetic; }
};

// Contact state and scratch (effects.contact). Rows are the elbows in
// `active`, in that order; p = active.size() changes only between steps.
struct ContactData {
  std::vector<bool> resting;              // [elbows] row of M* on
  std::vector<int> active;                // [p] elbow index of each row
  std::vector<Eigen::Vector3d> normal;    // [elbows] table normal under the elbow (world, unit)
  std::vector<Eigen::Vector3d> surface;   // [elbows] a point of the table surface there [m]
  Eigen::MatrixXd Jc;      // [p x n] rows j_ck = n_k^T J_k (eq. 8)
  Eigen::MatrixXd Jf;      // [p x n] Jc - mu Jt: where the normal force acts, with friction (eq. 9)
  Eigen::VectorXd gamma;   // [p] -n^T Jdot qd (eq. 15, 31), plus Baumgarte terms
  Eigen::VectorXd C, Cd;   // [p] constraint value [m] and rate [m/s]
  Eigen::VectorXd fn;      // [p] normal forces [N], > 0 when the table pushes
  Eigen::VectorXd slide;   // [p] sliding speed of each contact point [m/s]
  Eigen::MatrixXd Y, Z, A;       // scratch: L^-1 Jc^T, L^-1 Jf^T, Jc M^-1 Jf^T
  Eigen::VectorXd a_free, rhs;   // scratch [n], [p]
  Eigen::LLT<Eigen::MatrixXd> A_llt;         // A without friction (symmetric)
  Eigen::PartialPivLU<Eigen::MatrixXd> A_lu;  // A with friction
  Matrix3Xd J3;                  // scratch point Jacobian [3 x n]
  bool dependent = false;        // last solve met dependent rows
  double impact_loss = 0;        // [J] kinetic energy lost in impacts so far
  double projection_energy = 0;  // [J] stored-energy change made by projection so far
};

struct Controller;

struct Data {
  explicit Data(const Model& model);

  // --- state -------------------------------------------------------------
  double t = 0;             // [s]
  Eigen::VectorXd q;        // [n] joint angles [rad]
  Eigen::VectorXd qd;       // [n] joint rates [rad/s]
  Eigen::VectorXd current;  // [n] motor currents [A] (state only for motor: full)

  // --- stage outputs of the last derivative evaluation --------------------
  Eigen::VectorXd qdd;           // [n] joint accelerations [rad/s^2]
  Eigen::VectorXd voltage;       // [n] applied (saturated) motor voltage [V]
  Eigen::VectorXd current_rate;  // [n] di/dt [A/s] (motor: full)
  Eigen::VectorXd actuation;     // [n] Km i, or the input torque without motors [N m]

  // --- kinematics (forward_kinematics) ------------------------------------
  std::vector<Eigen::Matrix3d> rotation;  // [n] link frame -> world
  std::vector<Eigen::Vector3d> origin;    // [n] joint i position = link frame origin [m]
  std::vector<Eigen::Vector3d> axis;      // [n] joint axis, unit
  std::vector<Eigen::Vector3d> com;       // [n] link centre of mass [m]
  std::vector<Eigen::Matrix3d> inertia;   // [n] link inertia about its com [kg m^2]

  // --- dynamics scratch ----------------------------------------------------
  Eigen::MatrixXd mass_matrix;     // [n x n] M (+ Jm when rotor inertia is on)
  Eigen::VectorXd bias;            // [n] h + g + (D + Dm) qd
  Eigen::VectorXd tau;             // [n] scratch torque vector
  Eigen::VectorXd zero;            // [n] zeros, for calls that need "no qd/qdd"
  Eigen::VectorXd unit;            // [n] scratch unit vector (Walker-Orin columns)
  Eigen::LLT<Eigen::MatrixXd> llt;  // Cholesky of mass_matrix

  // Newton-Euler recursion, per link [n]
  std::vector<Eigen::Vector3d> omega, omega_dot, origin_acc, force, moment;
  // Spatial (Plucker, world origin) quantities of CRBA/ABA, per link [n]
  std::vector<Matrix6d> spatial_inertia, articulated_inertia;
  std::vector<Vector6d> motion_subspace, velocity, bias_acc, bias_force, acc, U;
  Eigen::VectorXd D, u;  // [n] ABA joint-space scratch

  // --- integrator state ----------------------------------------------------
  // x = [q; qd; i (motor: full); energy integrals] (state_vector.hpp)
  Eigen::VectorXd x, x_start, k1, k2, k3, k4, x_a, x_b, x_c;
  Eigen::ArrayXd lambda;  // stiff linear rates per component of x (derivative.hpp)
  // Exponential-integrator coefficients for one step length h (integrator.cpp):
  // `step` for the scene's step, `partial` for shortened steps (events, the end).
  struct StepCoefficients {
    double h = 0;
    Eigen::ArrayXd exp_h, exp_half, phi1_half, phi1_h, f1, f2, f3;
  } step, partial;

  ContactData contact;

  // --- task and controller ---------------------------------------------------
  std::shared_ptr<const Controller> controller;  // tracking controller and its plan; null: open loop
  Eigen::VectorXd q_desired, qd_desired, v_feedforward;  // [n] the plan at the stage time

  EnergyTerms energy;           // at time t
  EnergyTerms energy_initial;   // at t = 0
  long steps = 0;
};

}  // namespace elbowsim

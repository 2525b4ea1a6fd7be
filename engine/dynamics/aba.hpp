// Articulated-body algorithm: unconstrained forward dynamics in O(n), with the
// rotor inertia Jm entering as joint armature.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// qdd [n] = (M + Jm)^-1 (tau - h - G - (D + Dm) qd) for applied joint torques
// tau [n, N m]. Needs forward_kinematics(q). Allocates nothing.
void forward_dynamics_aba(const Model& model, Data& data, ConstVec qd,
                          ConstVec tau, Eigen::Ref<Eigen::VectorXd> qdd);

// The inward pass of ABA without velocities or torques: the articulated
// inertias' projections data.U [n] and data.D [n] (+ Jm), U / D, 1 / D and
// the coupling e_i at the current q, all that the response below needs.
// Needs forward_kinematics(q). O(n). (dynamics/articulated_inertias.cpp)
void articulated_inertias(const Model& model, Data& data);

// x [n] = (M + Jm)^-1 tau for joint torques tau [n] (no velocity, gravity or
// damping terms), from the U, D (U_over_D, D_inv, coupling) of the last
// articulated_inertias() or forward_dynamics_aba() at the same q: one inward
// and one outward sweep of 6-vectors, O(n); the inward sweep starts at tau's
// last non-zero entry (a contact row's torques end at its link).
// x may alias tau. (dynamics/aba_response.cpp)
void aba_response(const Model& model, const Data& data, ConstVec tau,
                  Eigen::Ref<Eigen::VectorXd> x);

// One column of a batch of responses: torques tau_j = tau[j * stride] for
// j = 0 .. n-1 (a row of a column-major matrix has stride = its rows) and
// the response x [n], contiguous; x may be the same memory as tau when the
// stride is 1.
struct ResponseColumn {
  const double* tau = nullptr;
  Eigen::Index stride = 1;
  double* x = nullptr;
};

// The responses of m columns at once (m >= 0), as aba_response() gives each:
// each sweep is a serial chain of 6-vector dots and updates, so sweeping up to
// kResponseBatch columns side by side runs their chains in parallel.
constexpr int kResponseBatch = 3;
void aba_responses(const Model& model, const Data& data, const ResponseColumn* columns, int m);

}  // namespace elbowsim

// Per-joint gains placed by one stated rule (docs/model.md, "Tuning"), so that
// two arms compared by a study are each tuned the same way rather than
// sharing one set of numbers that suits one of them.
//
// Each joint j is taken alone, linearised about the task's first pose q0:
//   I_j q'' = g_j v - c_j q'       I_j = M_jj(q0) + Jm_j   [kg m^2]
//                                  g_j = eta_j Km_j / R_j   [N m/V]
//                                  c_j = eta_j Km_j^2 / R_j + D_j + Dm_j  [N m s/rad]
// (quasi-static electrics, L/R neglected; the other joints, gravity and
// contact left to the feed-forward and the integral). With the error
// e = q_d - q and v = Kp e + Kd e' + Ki int(e), the closed loop's poles are
// placed at w = 2 pi bandwidth with damping zeta, and (integral > 0) a real
// pole at alpha w:
//   PD:  I s^2 + (g Kd + c) s + g Kp = I (s^2 + 2 zeta w s + w^2)
//   PID: I s^3 + (g Kd + c) s^2 + g Kp s + g Ki
//          = I (s^2 + 2 zeta w s + w^2)(s + alpha w)
// A joint whose own damping c already exceeds what the rule asks
// ((2 zeta + alpha) w I) gets Kd 0 and keeps the rule's speed: PID with the
// pair (w, zeta) and the integral pole moved out to a = c / I - 2 zeta w
// (Kp and Ki from (s^2 + 2 zeta w s + w^2)(s + a)); PD with a pole at w and
// the other at c / I - w (Kp = I w (c / I - w) / g; for c / I < 2 w, Kp as
// above: natural frequency w, damped c / (2 I w)). A warning names the
// poles it has.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

struct TuningRule {
  double bandwidth = 0;  // [Hz] f, w = 2 pi f; 0: no rule (the gains are given)
  double damping = 1.0;  // zeta of the complex pair
  double integral = 0;   // alpha: the integral pole at alpha w; 0: PD
  bool given() const { return bandwidth > 0; }
};

// One joint's linear loop as the rule sees it.
struct JointLoop {
  double inertia = 0;  // I [kg m^2]
  double gain = 0;     // g [N m/V]
  double damping = 0;  // c [N m s/rad]
};

struct TunedGains {
  Eigen::VectorXd kp, kd, ki;  // [V/rad], [V s/rad], [V/(rad s)]
  Eigen::VectorXd inertia;     // [kg m^2] I_j the rule used
  std::vector<std::string> warnings;  // joints whose Kd was clamped at 0
};

// Joint j's loop at the pose whose mass matrix (with Jm) is `mass_matrix`.
JointLoop joint_loop(const Model& model, const Eigen::MatrixXd& mass_matrix, int j);

// The closed-loop poles [rad/s] of a joint loop under the gains (kp, kd, ki):
// two for PD (ki 0), three for PID.
std::vector<std::complex<double>> closed_loop_poles(const JointLoop& loop, double kp, double kd,
                                                    double ki);

// Every joint's gains on `model` (the controller's: what it believes) at the
// pose q0. Needs motors (model.has_motor()).
TunedGains tune_gains(const Model& model, ConstVec q0, const TuningRule& rule);

}  // namespace elbowsim

// Linear stability of the fixed-step integrators (integrator.hpp) on the
// motor-arm system linearised at a pose (engine/MODEL.md, "Stability of the
// fixed steps"). With x = (q, qd, i) and the currents' -R/L taken exactly
// (the ETD part lambda), the explicit part N is, per joint block:
//   q'  = qd
//   qd' = M(q)^-1 (Km i - (D + Dm) qd)                       motor: full
//   i'  = -R/L i + (-(Km + Kd) qd - Kp q) / L
// (Kp, Kd: a continuous tracking controller's gains, in volts; a sampled loop
// holds its voltage, so it adds none); quasi_static puts i = (v - Km qd)/R into
// qd', none leaves qd' = -M^-1 (D + Dm) qd. Gravity's stiffness (|dG/dq| / M:
// a few s^-2) and the contact rows (they only lower the free arm's rates) are
// left out. One step maps x to A x; the step is stable when the spectral
// radius of A is at most 1.
#pragma once

#include <Eigen/Core>

#include "engine/control/controller.hpp"
#include "engine/model.hpp"

namespace elbowsim {

// x' = lambda .* x + N x: the linearised system of the header's comment.
struct LinearisedArm {
  int n = 0;               // joints: x = (q [n], qd [n], i [n] with motor: full)
  Eigen::VectorXd lambda;  // [size] -R/L on the currents, 0 on q and qd
  Eigen::MatrixXd N;       // [size x size], size = 2n (+ n with motor: full)
};

// The system at pose q [n]; controller: the feedback gains (null, open loop
// or sampled: none).
LinearisedArm linearise_arm(const Model& model, const ControllerSpec* controller,
                            const Eigen::VectorXd& q);

// A radius up to this counts as stable: a neutral mode (q without stiffness,
// a double eigenvalue 1) comes out 1 +- ~1e-9 by rounding, and a mode growing
// by 1e-6 per step takes a million steps to grow e-fold.
inline constexpr double kStableRadius = 1 + 1e-6;

// The spectral radius of one step of length h of a fixed-step integrator
// (euler, semi_implicit_euler, rk4) on the linearised system.
double amplification_radius(IntegratorKind kind, const LinearisedArm& arm, double h);

// About the longest stable step, searched from h: the boundary where the
// radius first exceeds kStableRadius, bracketed by 10 % steps from h (down
// when h is unstable, up when it is stable) and bisected to 0.1 %. Infinity
// when still stable at ~1e4 h (nothing stiff), 0 when still unstable at 1e-4 h.
double stable_step_limit(IntegratorKind kind, const LinearisedArm& arm, double h);

// auto (integrator_choice.hpp) keeps rk4 when it is stable at this multiple of
// the step at initial.q: along the shipped scenes' runs the stable step moved
// at most 13 % from its value there (singular_stretch; 9 % elbow_experiment).
inline constexpr double kStableMargin = 1.5;

// The analysis solves eigenvalue problems of size 2n or 3n, two per pose and up to
// about 110 more when the step is unstable (stable_step_limit): above this many
// joints it is not made. (At 256 joints one problem took 1.2 s, and every load of a
// scenario with simulation.integrator: auto made two.)
inline constexpr int kStabilityMaxJoints = 32;

// What the stability of the model's fixed step says at pose q:
struct FixedStepStability {
  double radius = 0;           // at options.step, for `kind`
  double radius_margin = 0;    // at kStableMargin x the step (what auto asks for)
  double stable_step = 0;      // [s] stable_step_limit when unstable at the step; else 0
  int fastest = -1;            // the joint with the smallest L/R (-1: no current state)
  double electrical_time = 0;  // [s] its L/R
};
FixedStepStability fixed_step_stability(const Model& model, IntegratorKind kind,
                                        const ControllerSpec* controller, const Eigen::VectorXd& q);

}  // namespace elbowsim

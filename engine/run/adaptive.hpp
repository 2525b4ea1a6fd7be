// Adaptive integrators with error control, for x' = f(t, x) = lambda .* x + N(t, x)
// (derivative.hpp), chosen by simulation.integrator:
//   dopri5    Dormand & Prince (1980) 5(4), explicit, 7 evaluations per step,
//             Hairer's PI step control and 4th-order continuous extension
//             (Hairer, Norsett & Wanner, Solving ODEs I, II.5 and II.6);
//   ros34pw2  Rang & Angermann (2005), a linearly implicit Rosenbrock-W method
//             of order 3(2), L-stable and stiffly accurate: the motor currents'
//             fast decay and their back-EMF coupling to the joint speeds are
//             taken implicitly through a Jacobian (finite differences of N over
//             q, qd, i; lambda exactly), 4 evaluations and one LU per step.
//             A W-method keeps its order for any Jacobian approximation, so the
//             Jacobian of the step's start serves every redo of the step.
// A step is accepted when the error norm (model.hpp, Options) is at most 1.
// dopri5 watches for stiffness as Hairer's DOPRI5 code does (Solving ODEs II,
// IV.2, (2.25)): after each accepted step, h |lambda| ~ h ||k7 - k6|| / ||x7 - x6||
// from its last two stages (both at t + h); above kStiffEdge for kStiffSteps
// accepted steps in a row (kNonstiffSteps below it reset the count), the run
// warns once (step_log.hpp, Warning::Kind::stiff).
// Steps end at every controller sample and at the end of the run (the caller's
// h_max); a located event shortens the accepted step and the next one starts
// afresh from the state after it.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// dopri5's stiffness test: its stability region meets the negative real axis
// near -3.3; Hairer's code flags h |lambda| > 3.25 for 15 steps, 6 below reset.
constexpr double kStiffEdge = 3.25;
constexpr int kStiffSteps = 15;
constexpr int kNonstiffSteps = 6;

// Advances data.x from data.t by one accepted step of at most h_max, trying
// data.adaptive.h_next first (options.step for the first step). Sets
// data.x_start to the step's start. Returns false with data.failure set when
// the step size underflows.
bool adaptive_step(const Model& model, Data& data, double h_max);

// Puts into data.x the state at t0 + tau, 0 < tau <= the last accepted step,
// from that step (started at data.x_start, time t0): dopri5 by its dense
// output, ros34pw2 by redoing the step over tau with the step's Jacobian.
void adaptive_redo(const Model& model, Data& data, double t0, double tau);

// The error norm of the estimate e for a step from x0 to x1.
double error_norm(const Options& options, ConstVec e, ConstVec x0, ConstVec x1);

}  // namespace elbowsim

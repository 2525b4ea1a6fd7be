// Whether a run's numbers can be trusted. A run is valid only when all hold:
//   - the state stays finite and below 1e12 (else it diverged);
//   - motor currents and joint speeds stay within a stated multiple of their
//     physical bounds (stall current, free-running speed: validity.*_factor);
//   - no link capsule and no elbow sphere is deeper in a table box than
//     contact.penetration_tolerance (with contact on or off: with contact off
//     the table is ignored by the physics, and a run that goes through it is
//     invalid, not quietly wrong);
//   - the energy balance closes to validity.energy_residual of the energy
//     that flowed;
//   - every elbow the task rests on the table rests there for
//     validity.rest_share of the run.
// A broken check sets data.failure (step_log.hpp) and the run stops.
#pragma once

#include "engine/data.hpp"
#include "engine/recording/metrics.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

// After a step, at the state in data.x: divergence, current and speed
// bounds, penetration. Runs forward kinematics at q. Allocates nothing.
void check_step(const Model& model, Data& data);

// At a recorded sample (stage outputs evaluated): the largest energy the arm
// held so far, and the first time the balance residual went beyond the bound.
void track_energy(const Model& model, Data& data);

// At the end of the run (the last sample evaluated): the energy balance closes
// to validity.energy_residual of the energy that flowed (in and out, each
// counted once, so regeneration cannot hide an error) plus the most the arm
// held (kinetic, potential since the start, magnetic: a frictionless
// pendulum exchanges energy without any flowing).
void check_energy(const Model& model, Data& data);

// The energy that flowed so far [J]: what went in (E_in, the hand force's
// and the table's work, projection) and what was lost, each as a magnitude.
double energy_flow(const EnergyTerms& now);

// What the arm holds now [J]: kinetic, potential since the start, magnetic.
double energy_held(const EnergyTerms& now, const EnergyTerms& initial);

// After the run: every elbow in `planned_resting` (model elbow indices)
// rested for validity.rest_share of the recording's duration.
void check_planned_rest(const Model& model, const std::vector<int>& planned_resting,
                        const Recording& recording, Data& data);

// The largest step [s] the integrator can take stably at the state in data:
// a fixed step's stability boundary on the motor-arm system linearised at its
// q with a tracking controller's gains (fixed_step_stability.hpp); for the
// adaptive integrators 2 over the arm's fastest damped and oscillatory rates
// (back-EMF damping Km^2/R, the controller's Km Kd/R and Km Kp/R). 0 when it
// cannot be estimated; infinity when nothing limits a fixed step.
double stable_step_estimate(const Model& model, Data& data);

}  // namespace elbowsim

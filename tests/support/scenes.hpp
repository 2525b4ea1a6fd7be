// Small scenes shared by the integrator, energy and simulator tests.
#pragma once

#include <limits>

#include "support/models.hpp"

namespace elbowsim::testing {

// Unactuated frictionless 2-link pendulum (motor none), released from rest.
Model pendulum(IntegratorKind integrator, double step, double duration);

// Unactuated frictionless single-link pendulum, released from rest at 1 rad.
Model simple_pendulum(IntegratorKind integrator, double step, double duration);

// 2-link arm driven by sine voltages through full DC motors, with gravity,
// damping and rotor inertia: smooth, every term of the model active.
Model driven_arm(IntegratorKind integrator, double step, double duration, double inductance);

// The model with the energy-balance validity check off (validity.energy_residual =
// infinity): for tests that measure integration error itself, at steps chosen to show it.
inline Model error_study(Model m) {
  m.validity.energy_residual = std::numeric_limits<double>::infinity();
  return m;
}

}  // namespace elbowsim::testing

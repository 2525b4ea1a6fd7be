// Small scenes shared by the integrator, energy and simulator tests.
#pragma once

#include "support/models.hpp"

namespace elbowsim::testing {

// Unactuated frictionless 2-link pendulum (motor none), released from rest.
Model pendulum(IntegratorKind integrator, double step, double duration);

// Unactuated frictionless single-link pendulum, released from rest at 1 rad.
Model simple_pendulum(IntegratorKind integrator, double step, double duration);

// 2-link arm driven by sine voltages through full DC motors, with gravity,
// damping and rotor inertia: smooth, every term of the model active.
Model driven_arm(IntegratorKind integrator, double step, double duration, double inductance);

}  // namespace elbowsim::testing

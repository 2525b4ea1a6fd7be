// simulation.integrator: auto, the default. The fixed-step rk4 where it is
// stable with a margin on the motor-arm system and resolves the motor
// electrics; ros34pw2 (implicit in them, adaptive.hpp) where it does not
// (engine/MODEL.md, "Stability of the fixed steps").
#pragma once

#include <string>

#include "engine/control/controller.hpp"
#include "engine/model.hpp"

namespace elbowsim {

struct IntegratorChoice {
  IntegratorKind kind = IntegratorKind::rk4;
  std::string reason;  // one sentence with the numbers that decided
};

// rk4 when, on the system linearised at initial.q (fixed_step_stability.hpp,
// with the controller's continuous feedback gains; null: none), one rk4 step
// is stable at options.step and at kStableMargin times it, and every motor's
// L/R is at least a tenth of the step (below it rk4 is first order:
// engine/MODEL.md); else ros34pw2. Above kStabilityMaxJoints joints, no analysis:
// ros34pw2.
IntegratorChoice choose_integrator(const Model& model, const ControllerSpec* controller);

}  // namespace elbowsim

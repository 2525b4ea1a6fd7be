#include "engine/run/integrator_choice.hpp"

#include <cstdio>

#include "engine/run/fixed_step_stability.hpp"

namespace elbowsim {

namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
  char text[400];
  std::snprintf(text, sizeof text, pattern, a, b, c, d);
  return text;
}

}  // namespace

IntegratorChoice choose_integrator(const Model& model, const ControllerSpec* controller) {
  const Eigen::VectorXd q =
      model.initial.q.size() == model.dof ? model.initial.q : Eigen::VectorXd::Zero(model.dof);
  const double h = model.options.step;
  IntegratorChoice choice;
  if (model.dof > kStabilityMaxJoints) {
    choice.kind = IntegratorKind::ros34pw2;
    choice.reason = format(
        "the arm has %.0f joints, more than the %.0f the fixed steps' stability analysis is "
        "made for (its eigenvalue problems grow as the cube of the joints); ros34pw2 is "
        "implicit in the motor-arm system, stable at any step",
        model.dof, kStabilityMaxJoints);
    return choice;
  }
  const FixedStepStability s = fixed_step_stability(model, IntegratorKind::rk4, controller, q);
  const bool unresolved = s.fastest >= 0 && s.electrical_time < 0.1 * h;
  if (unresolved) {
    choice.kind = IntegratorKind::ros34pw2;
    choice.reason =
        "motor " + std::to_string(s.fastest) +
        format(
            "'s L/R = %.3g s is under a tenth of the step %.3g s: rk4 would be first-order "
            "accurate there",
            s.electrical_time, h) +
        (s.radius > kStableRadius
             ? format(" and is unstable (one step amplifies errors %.3g times on the motor-arm "
                      "system linearised at initial.q; stable up to a step of about %.3g s)",
                      s.radius, s.stable_step)
             : std::string()) +
        "; ros34pw2 is implicit in the motor electrics";
    return choice;
  }
  if (s.radius > kStableRadius || s.radius_margin > kStableRadius) {
    choice.kind = IntegratorKind::ros34pw2;
    choice.reason =
        s.radius > kStableRadius
            ? format(
                  "rk4 is unstable at the step %.3g s on the motor-arm system linearised at "
                  "initial.q (one step amplifies errors %.3g times; stable up to a step of "
                  "about %.3g s); ros34pw2 is implicit in it",
                  h, s.radius, s.stable_step)
            : format(
                  "rk4 at the step %.3g s is within a factor %.3g of its stability limit on "
                  "the motor-arm system linearised at initial.q (one step of %.3g s amplifies "
                  "errors %.3g times); ros34pw2 is implicit in it",
                  h, kStableMargin, kStableMargin * h, s.radius_margin);
    return choice;
  }
  choice.reason = format(
      "rk4 is stable at %.3g times the step %.3g s on the motor-arm system linearised at "
      "initial.q (the spectral radius of one step of %.3g s is %.3g)",
      kStableMargin, h, kStableMargin * h, s.radius_margin);
  if (s.fastest >= 0)
    choice.reason +=
        format(" and resolves the motor electrics (smallest L/R %.3g s)", s.electrical_time);
  return choice;
}

}  // namespace elbowsim

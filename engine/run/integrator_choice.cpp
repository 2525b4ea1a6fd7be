#include "engine/run/integrator_choice.hpp"

#include "engine/recording/number_text.hpp"
#include "engine/run/fixed_step_stability.hpp"

namespace elbowsim {

IntegratorChoice choose_integrator(const Model& model, const ControllerSpec* controller) {
  const Eigen::VectorXd q =
      model.initial.q.size() == model.dof ? model.initial.q : Eigen::VectorXd::Zero(model.dof);
  const double h = model.options.step;
  IntegratorChoice choice;
  if (model.dof > kStabilityMaxJoints) {
    choice.kind = IntegratorKind::ros34pw2;
    choice.reason = "the arm has " + std::to_string(model.dof) + " joints, more than the " +
                    std::to_string(kStabilityMaxJoints) +
                    " the fixed steps' stability analysis is made for (its eigenvalue problems "
                    "grow as the cube of the joints); ros34pw2 is implicit in the motor-arm "
                    "system, stable at any step";
    return choice;
  }
  const FixedStepStability s = fixed_step_stability(model, IntegratorKind::rk4, controller, q);
  const bool unresolved = s.fastest >= 0 && s.electrical_time < 0.1 * h;
  if (unresolved) {
    choice.kind = IntegratorKind::ros34pw2;
    choice.reason =
        "motor " + std::to_string(s.fastest) + "'s L/R = " + significant(s.electrical_time, 3) +
        " s is under a tenth of the step " + significant(h, 3) +
        " s: rk4 would be first-order accurate there" +
        (s.radius > kStableRadius
             ? " and is unstable (one step amplifies errors " + significant(s.radius, 3) +
                   " times on the motor-arm system linearised at initial.q; stable up to a step "
                   "of about " +
                   significant(s.stable_step, 3) + " s)"
             : std::string()) +
        "; ros34pw2 is implicit in the motor electrics";
    return choice;
  }
  if (s.radius > kStableRadius || s.radius_margin > kStableRadius) {
    choice.kind = IntegratorKind::ros34pw2;
    choice.reason =
        s.radius > kStableRadius
            ? "rk4 is unstable at the step " + significant(h, 3) +
                  " s on the motor-arm system linearised at initial.q (one step amplifies "
                  "errors " +
                  significant(s.radius, 3) + " times; stable up to a step of about " +
                  significant(s.stable_step, 3) + " s); ros34pw2 is implicit in it"
            : "rk4 at the step " + significant(h, 3) + " s is within a factor " +
                  significant(kStableMargin, 3) +
                  " of its stability limit on the motor-arm system linearised at initial.q (one "
                  "step of " +
                  significant(kStableMargin * h, 3) + " s amplifies errors " +
                  significant(s.radius_margin, 3) + " times); ros34pw2 is implicit in it";
    return choice;
  }
  choice.reason =
      "rk4 is stable at " + significant(kStableMargin, 3) + " times the step " + significant(h, 3) +
      " s on the motor-arm system linearised at initial.q (the spectral radius of "
      "one step of " +
      significant(kStableMargin * h, 3) + " s is " + significant(s.radius_margin, 3) + ")";
  if (s.fastest >= 0)
    choice.reason += " and resolves the motor electrics (smallest L/R " +
                     significant(s.electrical_time, 3) + " s)";
  return choice;
}

}  // namespace elbowsim

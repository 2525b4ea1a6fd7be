// engine/run/integrator_choice.cpp: auto keeps rk4 where it is stable with a
// margin and resolves the electrics, picks ros34pw2 elsewhere, and says why
// with the numbers that decided.
#include <doctest/doctest.h>

#include <string>

#include "engine/run/fixed_step_stability.hpp"
#include "engine/run/integrator_choice.hpp"
#include "support/models.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The driven 2-link arm (support/scenes.hpp) at `step` with L = `inductance`.
Model arm(double step, double inductance) {
  return driven_arm(IntegratorKind::rk4, step, 1.0, inductance);
}

// The same with quasi-static motors: no electrical time, only the back-EMF
// damping (and a controller's gains) limit the step.
Model quasi(double step) {
  Model m = arm(step, 5e-4);
  m.effects.motor = MotorModel::quasi_static;
  finalize(m);
  return m;
}

double rk4_limit(const Model& m) {
  return stable_step_limit(IntegratorKind::rk4, linearise_arm(m, nullptr, m.initial.q),
                           m.options.step);
}

}  // namespace

TEST_CASE("auto: rk4 on a resolved, stable arm; ros34pw2 on electrics under a tenth of the step") {
  const IntegratorChoice resolved = choose_integrator(arm(1e-3, 5e-4), nullptr);  // L/R 0.25 ms
  MESSAGE(resolved.reason);
  CHECK(resolved.kind == IntegratorKind::rk4);
  CHECK(has(resolved.reason, "rk4 is stable at 1.5 times the step 0.001 s"));
  CHECK(has(resolved.reason, "smallest L/R 0.00025 s"));
  const IntegratorChoice stiff = choose_integrator(arm(1e-3, 1e-6), nullptr);  // L/R 0.5 us
  MESSAGE(stiff.reason);
  CHECK(stiff.kind == IntegratorKind::ros34pw2);
  CHECK(has(stiff.reason, "motor 0's L/R = 5e-07 s is under a tenth of the step 0.001 s"));
}

TEST_CASE("auto: ros34pw2 when rk4 is unstable at the step, or stable but not at 1.5 x it") {
  const double limit = rk4_limit(quasi(1e-3));
  MESSAGE("rk4 on the driven arm (quasi-static motors): stable up to ", limit, " s");
  // Below limit / 1.5: rk4; between: within the margin; above: unstable.
  CHECK(choose_integrator(quasi(0.6 * limit), nullptr).kind == IntegratorKind::rk4);
  const IntegratorChoice close = choose_integrator(quasi(0.8 * limit), nullptr);
  CHECK(close.kind == IntegratorKind::ros34pw2);
  CHECK(has(close.reason, "within a factor 1.5 of its stability limit"));
  const IntegratorChoice beyond = choose_integrator(quasi(1.2 * limit), nullptr);
  CHECK(beyond.kind == IntegratorKind::ros34pw2);
  CHECK(has(beyond.reason, "rk4 is unstable at the step"));
  CHECK(has(beyond.reason, "stable up to a step of about"));
}

TEST_CASE("auto: a tracking controller's continuous gains count; a sampled loop's do not") {
  Model m = quasi(1e-3);
  m.options.step = 0.5 * rk4_limit(m);  // rk4 with the margin, open loop
  finalize(m);
  CHECK(choose_integrator(m, nullptr).kind == IntegratorKind::rk4);
  ControllerSpec pd;
  pd.kind = ControllerSpec::Kind::pd;
  pd.kp = Eigen::Vector2d(50, 50);
  pd.kd = Eigen::Vector2d(20, 20);  // [V s/rad]: Km + Kd = 21.5 against Km = 1.5
  CHECK(choose_integrator(m, &pd).kind == IntegratorKind::ros34pw2);
  pd.loop.sample_period = 1e-3;
  CHECK(choose_integrator(m, &pd).kind == IntegratorKind::rk4);
}

TEST_CASE("auto: no analysis above 32 joints (ros34pw2, saying why); up to 32 the analysis decides") {
  const IntegratorChoice analysed = choose_integrator(random_chain(kStabilityMaxJoints, 7), nullptr);
  MESSAGE(analysed.reason);
  CHECK_FALSE(has(analysed.reason, "joints, more than"));
  CHECK(has(analysed.reason, "linearised at initial.q"));
  const IntegratorChoice long_arm = choose_integrator(random_chain(kStabilityMaxJoints + 1, 7), nullptr);
  MESSAGE(long_arm.reason);
  CHECK(long_arm.kind == IntegratorKind::ros34pw2);
  CHECK(has(long_arm.reason, "the arm has 33 joints, more than the 32 the fixed steps' stability "
                             "analysis is made for"));
}

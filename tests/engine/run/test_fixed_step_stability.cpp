// engine/run/fixed_step_stability.cpp: one step's amplification on the
// linearised motor-arm system, against the classical stability polynomials,
// the bounds engine/MODEL.md states, and runs just inside and outside them.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/run/fixed_step_stability.hpp"
#include "engine/run/simulator.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// One link turning about a horizontal axis, no gravity (nothing but the
// motor and the damping acts): J = I_c + m c^2 (+ Jm).
//   o====[ 0.5 m, 1 kg, c 0.25 m ]
Model one_joint(MotorModel motor) {
  Model m = planar_arm({{0.5, 1.0, 0.25, 0.02}});
  m.effects.gravity = false;
  m.effects.motor = motor;
  Motor servo = small_servo();  // K 0.03 N m/A, R 2 ohm
  servo.gear_ratio = 100;       // Km = 3 N m/A, Jm = 5e-3 kg m^2
  servo.gear_friction = 0;
  servo.inductance = 1e-9;  // L/R = 0.5 ns: hR/L ~ 1e7 at the steps below
  m.motors = {servo};
  m.initial.qd = Eigen::VectorXd::Constant(1, 1.0);
  m.options.duration = 50;
  finalize(m);
  return m;
}

double inertia(const Model& m) { return 0.02 + 1.0 * 0.25 * 0.25 + m.armature[0]; }

}  // namespace

TEST_CASE("amplification_radius: without motor electrics, the classical stability polynomials") {
  // qd' = -(d / J) qd: one step multiplies qd by R(z), z = -h d / J; q adds a
  // neutral mode (radius 1).
  Model m = planar_arm({{0.5, 1.0, 0.25, 0.02}});
  m.effects.damping = true;
  m.damping = Eigen::VectorXd::Constant(1, 2.0);
  finalize(m);
  const LinearisedArm arm = linearise_arm(m, nullptr, Eigen::VectorXd::Zero(1));
  const double J = 0.02 + 0.0625, d = 2.0;
  for (double z : {-0.5, -2.0, -2.7, -3.0}) {
    const double h = -z * J / d;
    const double rk4 = 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
    CAPTURE(z);
    CHECK(amplification_radius(IntegratorKind::rk4, arm, h) ==
          doctest::Approx(std::max(1.0, std::abs(rk4))).epsilon(1e-12));
    CHECK(amplification_radius(IntegratorKind::euler, arm, h) ==
          doctest::Approx(std::max(1.0, std::abs(1 + z))).epsilon(1e-12));
  }
  // The classical real-axis limits: RK4 2.785, Euler 2.
  CHECK(stable_step_limit(IntegratorKind::rk4, arm, 1e-3) * d / J ==
        doctest::Approx(2.785).epsilon(1e-3));
  CHECK(stable_step_limit(IntegratorKind::euler, arm, 1e-3) * d / J ==
        doctest::Approx(2.0).epsilon(1e-3));
}

TEST_CASE("stiff motor electrics: rk4 stable only for h Km^2 / (R J) < 1.455, not RK4's 2.785") {
  const Model m = one_joint(MotorModel::full);
  const double rate = m.km[0] * m.km[0] / m.resistance[0] / inertia(m);  // 9 / 0.0875 s^-1
  const LinearisedArm arm = linearise_arm(m, nullptr, Eigen::VectorXd::Zero(1));
  const double rk4 = stable_step_limit(IntegratorKind::rk4, arm, 1e-3);
  const double euler = stable_step_limit(IntegratorKind::euler, arm, 1e-3);
  MESSAGE("h Km^2/(R J) at the limit: rk4 ", rk4 * rate, ", euler ", euler * rate);
  // engine/MODEL.md's table, z = hR/L -> infinity (here ~3e7).
  CHECK(rk4 * rate == doctest::Approx(1.455).epsilon(2e-3));
  CHECK(euler * rate == doctest::Approx(1.0).epsilon(2e-3));
  // The quasi-static motor (i = (v - Km qd) / R, L -> 0 taken exactly) is
  // classical RK4 on the slow root: the stiff full model is the less stable.
  const Model quasi = one_joint(MotorModel::quasi_static);
  CHECK(stable_step_limit(IntegratorKind::rk4,
                          linearise_arm(quasi, nullptr, Eigen::VectorXd::Zero(1)), 1e-3) *
            rate ==
        doctest::Approx(2.785).epsilon(2e-3));
  // A continuous PD controller adds Km Kd / R to the back-EMF damping.
  ControllerSpec pd;
  pd.kind = ControllerSpec::Kind::pd;
  pd.kp = Eigen::VectorXd::Zero(1);
  pd.kd = Eigen::VectorXd::Constant(1, 3.0);  // [V s/rad]: doubles Km + Kd
  const double with_kd =
      stable_step_limit(IntegratorKind::rk4, linearise_arm(m, &pd, Eigen::VectorXd::Zero(1)), 1e-3);
  CHECK(with_kd * 2 * rate == doctest::Approx(1.455).epsilon(2e-3));
  // ... unless it is sampled: the amplifier holds its voltage between samples.
  pd.loop.sample_period = 1e-3;
  CHECK(stable_step_limit(IntegratorKind::rk4, linearise_arm(m, &pd, Eigen::VectorXd::Zero(1)),
                          1e-3) == doctest::Approx(rk4).epsilon(1e-9));
}

TEST_CASE(
    "the predicted limit is where the run's errors start to grow: bounded 3 % below, diverged 3 % "
    "above") {
  for (IntegratorKind kind : {IntegratorKind::rk4, IntegratorKind::euler}) {
    Model m = one_joint(MotorModel::full);
    m.options.integrator = kind;
    const double limit =
        stable_step_limit(kind, linearise_arm(m, nullptr, Eigen::VectorXd::Zero(1)), 1e-3);
    CAPTURE(to_string(kind));
    // Released at 1 rad/s with zero volts, the back-EMF brakes the joint to
    // rest (time constant J R / Km^2 ~ 10 ms); 2000 steps.
    m.options.step = 0.97 * limit;
    m.options.duration = 2000 * m.options.step;
    finalize(m);
    const RunResult below = simulate(m, {});
    INFO(below.failure);
    CHECK(below.completed);
    CHECK(std::abs(below.trajectory.at(below.trajectory.rows() - 1,
                                       below.trajectory.column("qd0"))) < 1e-6);
    m.options.step = 1.03 * limit;
    m.options.duration = 2000 * m.options.step;
    finalize(m);
    const RunResult above = simulate(m, {});
    CHECK_FALSE(above.completed);
    CHECK(above.failure.find("diverged") != std::string::npos);
  }
}

TEST_CASE(
    "fixed_step_stability: the radius at the step and at kStableMargin x it, the fastest L/R") {
  Model m = one_joint(MotorModel::full);
  m.motors[0].inductance = 2e-9;
  finalize(m);
  const LinearisedArm arm = linearise_arm(m, nullptr, Eigen::VectorXd::Zero(1));
  const double limit = stable_step_limit(IntegratorKind::rk4, arm, 1e-3);
  m.options.step = 0.8 * limit;  // stable, but not at 1.5 x
  finalize(m);
  FixedStepStability s =
      fixed_step_stability(m, IntegratorKind::rk4, nullptr, Eigen::VectorXd::Zero(1));
  CHECK(s.radius <= kStableRadius);
  CHECK(s.radius_margin > kStableRadius);
  CHECK(s.stable_step == 0);  // only searched when unstable at the step
  CHECK(s.fastest == 0);
  CHECK(s.electrical_time == doctest::Approx(1e-9));
  m.options.step = 1.2 * limit;
  finalize(m);
  s = fixed_step_stability(m, IntegratorKind::rk4, nullptr, Eigen::VectorXd::Zero(1));
  CHECK(s.radius > kStableRadius);
  CHECK(s.stable_step == doctest::Approx(limit).epsilon(2e-3));
  // Without a current state there is no electrical time.
  m.effects.motor = MotorModel::quasi_static;
  finalize(m);
  s = fixed_step_stability(m, IntegratorKind::rk4, nullptr, Eigen::VectorXd::Zero(1));
  CHECK(s.fastest == -1);
}

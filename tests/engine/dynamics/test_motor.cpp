// engine/dynamics/motor.cpp: the DC motor model (eq. 16-27), motor_stage on its own and
// against analytic cases of whole runs.
#include <doctest/doctest.h>

#include <algorithm>

#include "engine/run/simulator.hpp"
#include "engine/control/controller.hpp"
#include "engine/dynamics/motor.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;
using elbowsim::testing::last;

namespace {

// One link spinning about a vertical axis, so gravity does no work.
//   z ^   axis
//     |  /
//     o----- link (horizontal)
Model spinner(MotorModel motor_model, double volts) {
  Model m = elbowsim::testing::planar_arm({{0.3, 1.0, 0.15, 0.01}});
  m.joints[0].axis = Eigen::Vector3d::UnitZ();
  m.effects.motor = motor_model;
  m.effects.damping = false;
  m.effects.rotor_inertia = true;
  m.motors = {elbowsim::testing::small_servo()};
  m.inputs.quantity = OpenLoopInputs::Quantity::voltage;
  InputProfile v;
  v.kind = InputProfile::Kind::constant;
  v.value = volts;
  m.inputs.joints = {v};
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("motor: stalled rotor draws i = V/R and gives torque Km V/R") {
  const Model model = spinner(MotorModel::full, 6.0);
  Data data(model);
  const Eigen::VectorXd qd = Eigen::VectorXd::Zero(1);
  // Steady state of L di/dt = v - R i at qd = 0.
  const Eigen::VectorXd i = Eigen::VectorXd::Constant(1, 6.0 / 2.0);
  command(model, data, 0.0, qd, qd);
  motor_stage(model, data, qd, i);
  CHECK(data.current_rate[0] == doctest::Approx(0.0));
  CHECK(data.actuation[0] == doctest::Approx(0.03 * 50 * 6.0 / 2.0).epsilon(1e-14));
  // And a held rotor driven through the electrical transient settles there.
  Model held = model;
  held.links[0].mass = 1e9;  // effectively stalled
  held.links[0].inertia *= 1e9;
  held.options = {0.02, 1e-5, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(held);
  const RunResult r = simulate(held, {});
  CHECK(approx(last(r, "i0"), 3.0, 1e-6));  // 40 L/R time constants: e^-40 ~ 4e-18
}

TEST_CASE("motor: free spinning without gravity or friction reaches qd = V/Km") {
  Model model = spinner(MotorModel::full, 6.0);
  model.options = {3.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::aba};
  const RunResult r = simulate(model, {});
  // Mechanical time constant J R / Km^2 = (0.01+0.0225*... ) small; 3 s is many of them.
  CHECK(approx(last(r, "qd0"), 6.0 / (0.03 * 50), 1e-9, 1e-9));
  CHECK(approx(last(r, "i0"), 0.0, 1e-9));
}

TEST_CASE("motor: quasi-static and full models agree as L -> 0") {
  double previous_gap = 1e9;
  Model quasi = spinner(MotorModel::quasi_static, 4.0);
  quasi.options = {0.5, 1e-4, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(quasi);
  const double qd_quasi = last(simulate(quasi, {}), "qd0");
  for (double L : {1e-3, 1e-4, 1e-5}) {
    Model full = spinner(MotorModel::full, 4.0);
    full.motors[0].inductance = L;
    full.options = quasi.options;
    finalize(full);
    const double gap = std::abs(last(simulate(full, {}), "qd0") - qd_quasi);
    CAPTURE(L);
    CHECK(gap < previous_gap);
    previous_gap = gap;
  }
  // Gap is O(L/R): electrical lag 5 us against mechanical time scales of ~0.05 s.
  CHECK(previous_gap < 1e-3 * std::abs(qd_quasi));
}

TEST_CASE("motor: voltage saturates at the limit") {
  const Model model = spinner(MotorModel::quasi_static, 100.0);
  Data data(model);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(1);
  command(model, data, 0.0, zero, zero);
  motor_stage(model, data, zero, data.current);
  CHECK(data.voltage[0] == 24.0);
  CHECK(data.current[0] == doctest::Approx(12.0));
}

TEST_CASE("motor_stage directly: full, quasi-static and none on a commanded voltage") {
  // Two joints, small_servo: R = 2 ohm, L = 0.5 mH, Km = K k = 0.03 * 50 = 1.5 N m/A, 24 V.
  // Values chosen so that every product is exact in binary: the checks are ==.
  Model model = elbowsim::testing::planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.2, 0.5, 0.1, 0.005}});
  model.motors = {elbowsim::testing::small_servo(), elbowsim::testing::small_servo()};
  const Eigen::Vector2d qd(1.0, -2.0), current(1.25, -0.5);
  SUBCASE("full: di/dt = (v - R i - Km qd) / L, current copied from the state, torque Km i") {
    model.effects.motor = MotorModel::full;
    finalize(model);
    Data data(model);
    data.voltage = Eigen::Vector2d(6.0, -3.0);
    motor_stage(model, data, qd, current);
    CHECK(data.voltage == Eigen::Vector2d(6.0, -3.0));
    CHECK(data.current == current);
    CHECK(data.current_rate[0] == doctest::Approx((6.0 - 2.0 * 1.25 - 1.5 * 1.0) / 0.5e-3).epsilon(1e-15));
    CHECK(data.current_rate[1] == doctest::Approx((-3.0 - 2.0 * -0.5 - 1.5 * -2.0) / 0.5e-3).epsilon(1e-15));
    CHECK(data.actuation == Eigen::Vector2d(1.5 * 1.25, 1.5 * -0.5));
  }
  SUBCASE("quasi-static: i = (v - Km qd) / R, the state's current ignored, no di/dt") {
    model.effects.motor = MotorModel::quasi_static;
    finalize(model);
    Data data(model);
    data.voltage = Eigen::Vector2d(6.0, -3.0);
    motor_stage(model, data, qd, current);
    CHECK(data.current == Eigen::Vector2d((6.0 - 1.5) / 2.0, (-3.0 + 3.0) / 2.0));
    CHECK(data.actuation == Eigen::Vector2d(1.5 * 2.25, 0.0));
    CHECK(data.current_rate.isZero());
  }
  SUBCASE("none: the command already is the joint torque; nothing changes") {
    model.effects.motor = MotorModel::none;
    finalize(model);
    Data data(model);
    data.actuation = Eigen::Vector2d(0.7, -0.3);
    data.voltage = Eigen::Vector2d(100.0, -100.0);
    motor_stage(model, data, qd, current);
    CHECK(data.actuation == Eigen::Vector2d(0.7, -0.3));
    CHECK(data.voltage == Eigen::Vector2d(100.0, -100.0));
    CHECK(data.current.isZero());
    CHECK(data.current_rate.isZero());
  }
}

TEST_CASE("motor_stage saturates each joint at its own limit, both signs, before the electrics") {
  CHECK(saturate(30.0, 24.0) == 24.0);
  CHECK(saturate(-30.0, 24.0) == -24.0);
  CHECK(saturate(23.5, 24.0) == 23.5);
  CHECK(saturate(-24.0, 24.0) == -24.0);
  Model model = elbowsim::testing::planar_arm({{0.3, 1.0, 0.15, 0.01}, {0.2, 0.5, 0.1, 0.005}});
  model.motors = {elbowsim::testing::small_servo(), elbowsim::testing::small_servo()};
  model.motors[1].voltage_limit = 12.0;
  model.effects.motor = MotorModel::quasi_static;
  finalize(model);
  Data data(model);
  const Eigen::Vector2d rest = Eigen::Vector2d::Zero();
  for (const double command : {30.0, -30.0, 10.0}) {
    CAPTURE(command);
    data.voltage = Eigen::Vector2d::Constant(command);
    motor_stage(model, data, rest, rest);
    const Eigen::Vector2d applied(std::clamp(command, -24.0, 24.0), std::clamp(command, -12.0, 12.0));
    CHECK(data.voltage == applied);
    CHECK(data.current == applied / 2.0);  // stalled: i = v / R with the saturated v
  }
}

TEST_CASE("amplifier current limit: |i| stays within it (quasi-static exactly, full model from inside)") {
  // 6 V on a stalled rotor: i = V / R = 3 A without a limit.
  for (MotorModel kind : {MotorModel::quasi_static, MotorModel::full}) {
    CAPTURE(static_cast<int>(kind));
    Model m = spinner(kind, 6.0);
    m.motors[0].current_limit = 1.25;
    m.links[0].mass = 1e9;  // effectively stalled
    m.links[0].inertia *= 1e9;
    m.options = {0.02, 1e-5, IntegratorKind::rk4, DynamicsMethod::crba};
    finalize(m);
    const RunResult r = simulate(m, {});
    REQUIRE(r.valid);
    const int i0 = r.trajectory.column("i0");
    double largest = 0;
    for (std::size_t row = 0; row < r.trajectory.rows(); ++row)
      largest = std::max(largest, std::abs(r.trajectory.at(row, i0)));
    CHECK(largest <= 1.25 * (1 + 1e-12));
    CHECK(approx(last(r, "i0"), 1.25, 1e-6));  // held at the limit (40 L/R in the full model)
    CHECK(approx(last(r, "v0"), 2.0 * 1.25, 1e-6));  // the amplifier gives R i_max, not 6 V
  }
  // Spinning: the window moves with the back-EMF (Km qd + R i_max).
  Model m = spinner(MotorModel::quasi_static, 20.0);
  m.motors[0].current_limit = 0.5;
  finalize(m);
  Data data(m);
  const Eigen::VectorXd qd = Eigen::VectorXd::Constant(1, 0.1);
  data.voltage[0] = 20.0;
  motor_stage(m, data, qd, qd);
  CHECK(data.current[0] == doctest::Approx(0.5));
  CHECK(data.voltage[0] == doctest::Approx(m.km[0] * 0.1 + 2.0 * 0.5));
}

TEST_CASE("gear efficiency: efficiency x Km i when the motor drives, Km i / backdrive when the load drives") {
  Model m = spinner(MotorModel::quasi_static, 6.0);
  m.motors[0].efficiency = 0.8;
  m.motors[0].backdrive_efficiency = 0.7;
  finalize(m);
  REQUIRE(m.gear_losses);
  Data data(m);
  const double km = m.km[0];
  // Driving: torque and speed the same way.
  Eigen::VectorXd qd = Eigen::VectorXd::Constant(1, 0.5);
  data.voltage[0] = 6.0;
  motor_stage(m, data, qd, qd);
  const double i = (6.0 - km * 0.5) / 2.0;
  CHECK(data.actuation[0] == doctest::Approx(0.8 * km * i).epsilon(1e-14));
  CHECK(data.gear_loss_power == doctest::Approx(0.2 * km * i * 0.5).epsilon(1e-14));
  // Back-driven: the motor brakes a joint turning the other way.
  qd[0] = -0.5;
  motor_stage(m, data, qd, qd);
  const double ib = (6.0 + km * 0.5) / 2.0;
  CHECK(data.actuation[0] == doctest::Approx(km * ib / 0.7).epsilon(1e-14));
  CHECK(data.gear_loss_power > 0);  // (1 - 1/0.7) Km i qd with Km i qd < 0
  CHECK(data.gear_loss_power == doctest::Approx(km * ib * -0.5 * (1 - 1 / 0.7)).epsilon(1e-14));
}

TEST_CASE("gear efficiency: driven up and braked by a shorted motor, the balance closes with E_gear") {
  double previous = 1e300;
  for (double step : {2e-4, 1e-4}) {
    CAPTURE(step);
    Model m = spinner(MotorModel::full, 6.0);
    m.motors[0].efficiency = 0.8;
    m.motors[0].backdrive_efficiency = 0.7;
    m.inputs.joints[0].kind = InputProfile::Kind::steps;
    m.inputs.joints[0].times = {0.0, 0.3};
    m.inputs.joints[0].values = {6.0, 0.0};  // then shorted: the motor brakes the spinner
    m.options = {0.6, step, IntegratorKind::rk4, DynamicsMethod::crba};
    finalize(m);
    const RunResult r = simulate(m, RunOptions{1, {}});
    REQUIRE(r.valid);
    const double relative = std::abs(r.balance_residual) / r.energy_final.electrical_in;
    MESSAGE("step ", step, ": E_in ", r.energy_final.electrical_in, " J, E_gear ",
            r.energy_final.gear_loss, " J, |residual| / E_in ", relative);
    CHECK(r.energy_final.gear_loss > 0.1 * r.energy_final.electrical_in * 0.2);  // a real share
    CHECK(r.trajectory.column("E_gear") >= 0);
    // The gear switches branch where the motor torque crosses zero (a kink in
    // the joint torque, not located as an event): second order there, so the
    // residual falls at least 4x per halving, and stays far inside the
    // validity bound (1e-3 of the energy that flowed).
    CHECK(relative < 1e-3);
    CHECK(relative < previous / 4);
    previous = relative;
  }
}

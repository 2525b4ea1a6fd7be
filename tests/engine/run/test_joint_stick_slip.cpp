// engine/run/joint_stick_slip.cpp: a joint with dry friction, against
// analytic cases. One link turning about a vertical axis (no gravity) under
// a torque input: below its breakaway torque it does not move at all; above
// it, it slides with the friction torque opposing; when the torque goes, it
// stops at the time Coulomb's law gives and stays stuck. The energy balance
// closes with the friction loss as its own term.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/run/joint_stick_slip.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/contact_scenes.hpp"
#include "support/models.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using elbowsim::testing::last;

namespace {

constexpr double kInertia = 0.01 + 1.0 * 0.15 * 0.15;  // about the joint [kg m^2]

// A turntable link: torque `push` until `until`, then none; Coulomb tau_c,
// breakaway tau_s.
Model turntable(double push, double until, double coulomb, double breakaway) {
  Model m = testing::planar_arm({{0.3, 1.0, 0.15, 0.01}});
  m.joints[0].axis = Eigen::Vector3d::UnitZ();
  m.effects.motor = MotorModel::none;
  m.effects.damping = false;
  m.effects.joint_friction = true;
  m.joint_friction = {{coulomb, breakaway, 0.01}};
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  InputProfile p;
  p.kind = InputProfile::Kind::steps;
  p.times = {0.0, until};
  p.values = {push, 0.0};
  m.inputs.joints = {p};
  m.options = {1.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

double largest_speed(const RunResult& r) {
  const int qd = r.trajectory.column("qd0");
  double v = 0;
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row)
    v = std::max(v, std::abs(r.trajectory.at(row, qd)));
  return v;
}

}  // namespace

TEST_CASE("joint friction: loaded below its breakaway torque the joint stays stuck (speed exactly 0)") {
  const RunResult r = simulate(turntable(0.9 * 0.5, 10.0, 0.3, 0.5), RunOptions{1, {}});
  REQUIRE(r.valid);
  CHECK(largest_speed(r) == 0.0);
  CHECK(last(r, "q0") == r.trajectory.at(0, r.trajectory.column("q0")));
  CHECK(r.energy_final.joint_friction == 0.0);
}

TEST_CASE("joint friction: above breakaway it slides, the friction torque opposing (Coulomb at speed)") {
  // Breakaway = Coulomb (no Stribeck peak): qdd = (push - tau_c) / I exactly.
  const double push = 0.8, tau_c = 0.3;
  const RunResult r = simulate(turntable(push, 10.0, tau_c, tau_c), RunOptions{1, {}});
  REQUIRE(r.valid);
  const double a = (push - tau_c) / kInertia;
  CHECK(last(r, "qd0") == doctest::Approx(a * 1.0).epsilon(1e-9));
  CHECK(last(r, "q0") == doctest::Approx(0.5 * a).epsilon(1e-9));
  // The friction loss is tau_c times the angle turned; the balance closes.
  CHECK(r.energy_final.joint_friction == doctest::Approx(tau_c * 0.5 * a).epsilon(1e-9));
  CHECK(std::abs(r.balance_residual) < 1e-9 * r.energy_final.electrical_in);
}

TEST_CASE("joint friction: pushed, then let go, the joint stops when Coulomb's law says and stays stuck") {
  const double push = 0.8, tau_c = 0.3, until = 0.2;
  double previous_residual = 1e300;
  for (double step : {1e-3, 2.5e-4}) {
    CAPTURE(step);
    Model m = turntable(push, until, tau_c, 0.5);
    m.options.step = step;
    finalize(m);
    const RunResult r = simulate(m, RunOptions{1, {}});
    REQUIRE(r.valid);
    // The stop: the located step end where the speed is (to rounding) zero,
    // found by stepping by hand (rows fall on the step grid, not on events).
    double speed_at_release = 0, stop = -1;
    {
      Data data(m);
      reset(m, data);
      while (!finished(m, data) && stop < 0) {
        elbowsim::step(m, data);
        if (data.t <= until + 1e-12) speed_at_release = data.x[1];
        if (data.t > until && std::abs(data.x[1]) <= kJointStickSpeed) stop = data.t;
      }
    }
    // Without the push w' = -tau(w) / I, so the stop comes int_0^w1 dw / tau(w)
    // x I after the release (midpoint rule on 1e6 cells; Stribeck raises tau near 0).
    const JointFriction f{tau_c, 0.5, 0.01};
    double integral = 0;
    const int cells = 1000000;
    for (int k = 0; k < cells; ++k) {
      const double w = (k + 0.5) * speed_at_release / cells;
      const double wr = w / f.stribeck_velocity;
      integral += (speed_at_release / cells) / (f.coulomb + (f.breakaway - f.coulomb) * std::exp(-wr * wr));
    }
    const double expected = until + kInertia * integral;
    const double residual = std::abs(r.balance_residual) / r.energy_final.electrical_in;
    MESSAGE("step ", step, ": released at ", speed_at_release, " rad/s; stop located at ", stop,
            " s, expected ", expected, " s; |balance residual| / E_in = ", residual);
    REQUIRE(stop > 0);
    // RK4 crosses the Stribeck zone (0.01 rad/s wide: under a millisecond at
    // this deceleration) within a step or two: the stop time is that accurate.
    CHECK(std::abs(stop - expected) < 1e-5);
    CHECK(last(r, "qd0") == 0.0);  // stuck to the end
    CHECK(residual < 1e-5);
    CHECK(residual < previous_residual);  // integration error: it falls with the step
    previous_residual = residual;
  }
}

TEST_CASE("decide_joint_modes: a joint at rest whose load exceeds breakaway is set sliding against its holding torque") {
  Model m = turntable(-0.9, 10.0, 0.3, 0.5);
  Data data(m);
  reset(m, data);  // decides the modes at t = 0
  CHECK(data.joint_mode[0] == -1);  // pushed negative beyond breakaway
  Model held = turntable(-0.4, 10.0, 0.3, 0.5);
  Data d2(held);
  reset(held, d2);
  CHECK(d2.joint_mode[0] == 0);
  CHECK(d2.joint_friction_torque[0] == doctest::Approx(0.4));  // holds the push
}

// The ElbowArm (tests/support/contact_scenes.hpp) with dry friction at the
// elbow joint only, no inputs: the table carries the shoulder's moment through
// the elbow (frictionless contact), the joint's friction holds the forearm.
static Model leaning_arm(double breakaway_over_g2) {
  const testing::ElbowArm arm;
  Model m = arm.model(0.0, 0.0);
  m.inputs.joints.clear();
  m.effects.joint_friction = true;
  const double breakaway = breakaway_over_g2 * std::abs(arm.G2());
  m.joint_friction = {{0.0, 0.0, 0.01}, {0.8 * breakaway, breakaway, 0.01}};
  m.options.duration = 0.5;
  finalize(m);
  return m;
}

TEST_CASE("joint friction with a resting elbow: stuck joint and table share the load as statics say") {
  // Breakaway twice the forearm's gravity torque G2: nothing moves; the
  // elbow joint holds G2 and the table f = G1 / (l1 cos q1) (hand-derived,
  // ElbowArm::statics_force with no shoulder torque). Tolerances: the
  // Baumgarte-stabilised contact holds the elbow to ~1e-12 m, so q drifts by
  // far less than 1e-9 rad; forces to 1e-9 relative (one Cholesky of a 2 x 2).
  const testing::ElbowArm arm;
  const Model m = leaning_arm(2.0);
  Data data(m);
  reset(m, data);
  const Eigen::VectorXd q0 = data.x.head(2);
  while (!finished(m, data)) {
    step(m, data);
    REQUIRE(!data.failure);
  }
  CHECK((data.x.head(2) - q0).norm() < 1e-9);
  CHECK(data.joint_mode[1] == 0);
  REQUIRE(data.contact.active.size() == 1);
  CHECK(data.joint_friction_torque[1] == doctest::Approx(arm.G2()).epsilon(1e-9));
  CHECK(data.contact.fn[0] == doctest::Approx(arm.statics_force(0.0)).epsilon(1e-9));
  CHECK(data.joint_friction_torque[0] == 0.0);  // the frictionless shoulder
}

TEST_CASE("joint friction with a resting elbow: below G2 the forearm falls against Coulomb's torque") {
  // Breakaway half of G2: the forearm breaks away at once and turns down
  // (q2 falls) with the friction torque +tau_c opposing; the elbow stays on
  // the table and the energy balance closes with the joint's friction loss.
  const Model m = leaning_arm(0.5);
  const RunResult r = simulate(m, RunOptions{1, {}});
  REQUIRE(r.valid);
  const double q2_start = r.trajectory.at(0, r.trajectory.column("q1"));
  CHECK(last(r, "q1") < q2_start - 0.05);
  double fastest = 0;  // it turned down (it may come to rest again, e.g. on the table)
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row)
    fastest = std::min(fastest, r.trajectory.at(row, r.trajectory.column("qd1")));
  CHECK(fastest < -0.1);
  MESSAGE("forearm: q2 ", q2_start, " -> ", last(r, "q1"), " rad, fastest ", fastest,
          " rad/s; friction loss ", r.energy_final.joint_friction, " J; residual ", r.balance_residual, " J");
  CHECK(r.energy_final.joint_friction > 0);
  // The loss it reports is its torque times the angle turned, to the
  // accuracy of the balance (which closes to 1e-6 of the energy that flowed).
  CHECK(std::abs(r.balance_residual) < 1e-6 * std::abs(r.energy_final.potential - r.energy_initial.potential));
}

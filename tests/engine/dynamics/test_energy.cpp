// engine/dynamics/energy.cpp: stored energy (links, rotors, gravity, inductance) against
// hand-computed values, and the energy account: the balance E_in - losses - change of
// stored energy closes up to integration error, and the error falls with the step.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("energy balance residual < 1e-6 E_in for a damped motor-driven run, falling with step") {
  // L/R = 0.25 ms: at these steps the electrics are resolved (at 1 ms they are
  // stiff and the residual is ~1e-5 E_in, see docs/model.md).
  double previous = 1e300;
  for (double step : {2e-4, 1e-4, 5e-5}) {
    CAPTURE(step);
    const RunResult r = simulate(driven_arm(IntegratorKind::rk4, step, 2.0, 0.5e-3), {});
    REQUIRE(r.completed);
    const double relative = std::abs(r.balance_residual) / r.energy_final.electrical_in;
    MESSAGE("step ", step, ": |residual| / E_in = ", relative, ", E_in = ",
            r.energy_final.electrical_in, " J");
    CHECK(r.energy_final.joule > 0);
    CHECK(r.energy_final.viscous > 0);
    CHECK(relative < previous);
    previous = relative;
  }
  CHECK(previous < 1e-6);
}

TEST_CASE("energy: every term is recorded and the stored energy matches 1/2 qd^T (M+Jm) qd + PE") {
  const RunResult r = simulate(driven_arm(IntegratorKind::rk4, 1e-3, 0.3, 0.5e-3), {});
  const Recording& t = r.trajectory;
  for (const char* name : {"E_in", "E_joule", "E_viscous", "KE_links", "KE_rotors", "PE",
                           "E_magnetic", "balance_residual"})
    CHECK(t.column(name) >= 0);
  CHECK(r.energy_final.kinetic_rotors > 0);
  CHECK(r.energy_final.magnetic > 0);
}

TEST_CASE("energy without motors: input is the work of the applied torques") {
  Model m = pendulum(IntegratorKind::rk4, 1e-3, 1.0);
  InputProfile torque;
  torque.kind = InputProfile::Kind::constant;
  torque.value = 2.0;
  m.inputs.quantity = OpenLoopInputs::Quantity::torque;
  m.inputs.joints = {torque, InputProfile{}};
  finalize(m);
  const RunResult r = simulate(m, {});
  // The work of a constant torque on joint 0 is 2 N m times its angle change.
  const double dq0 = r.trajectory.at(r.trajectory.rows() - 1, 1) - r.trajectory.at(0, 1);
  CHECK(r.energy_final.electrical_in == doctest::Approx(2.0 * dq0).epsilon(1e-9));
  CHECK(std::abs(r.balance_residual) < 1e-9 * std::abs(r.energy_final.electrical_in) + 1e-12);
}

TEST_CASE("energy with a constant hand force: its work is F . (x_end - x_start), counted once") {
  // A constant force does work F . displacement; the balance must close with
  // it counted once, with and without motors, with and without an elbow resting.
  const Eigen::Vector3d force(0.3, 0, -1.0);
  auto check = [&](Model m, const std::string& what) {
    m.hand_load.force = force;
    finalize(m);
    const RunResult r = simulate(m, {});
    REQUIRE(r.completed);
    const Recording& rec = r.trajectory;
    const TrajectoryLayout& L = rec.layout;
    const std::size_t last = rec.rows() - 1;
    Eigen::Vector3d moved;
    for (int a = 0; a < 3; ++a) moved[a] = rec.at(last, L.hand(a)) - rec.at(0, L.hand(a));
    CAPTURE(what);
    CHECK(r.energy_final.external == doctest::Approx(force.dot(moved)).epsilon(1e-9));
    CHECK(std::abs(force.dot(moved)) > 1e-3);  // the force did work
    const double flow = std::abs(r.energy_final.electrical_in) + std::abs(r.energy_final.external);
    MESSAGE(what, ": hand-force work ", r.energy_final.external, " J, balance residual ", r.balance_residual, " J");
    // Integration error only (RK4): measured 2e-9 of the energy that flowed at
    // worst; counting the work twice would leave a residual of the order of 1.
    CHECK(std::abs(r.balance_residual) < 1e-7 * flow);
  };
  check(pendulum(IntegratorKind::rk4, 1e-3, 1.0), "pendulum, no motor");
  check(driven_arm(IntegratorKind::rk4, 1e-4, 0.5, 0.5e-3), "driven arm, full motors");
  const ElbowArm arm;
  Model resting = arm.model(0.5 * arm.G1(), 0.0);
  resting.options.duration = 0.5;
  check(resting, "elbow resting, torque inputs");
}

TEST_CASE("stored_energy of a single link == 1/2 (I + m lc^2) w^2 + m g h, + rotor and magnet") {
  // Planar link (axis -y, angle q from +x toward +z) on a base 0.3 m up: the com is at
  // height h = 0.3 + lc sin q, and the link turns about its joint at rate w.
  const double l = 0.5, m = 1.3, lc = 0.2, I = 0.021, g = 9.81, z0 = 0.3;
  for (MotorModel motor : {MotorModel::none, MotorModel::quasi_static, MotorModel::full}) {
    Model model = planar_arm({{l, m, lc, I}});
    model.base.translation() = Eigen::Vector3d(0.1, -0.2, z0);
    model.effects.motor = motor;
    model.motors = {small_servo()};  // Im k^2 = 5e-7 * 50^2, L = 0.5e-3 H
    finalize(model);
    Data data(model);
    for (double q : {0.0, 0.7, -1.2}) {
      const double w = 1.7, i = 2.5;
      forward_kinematics(model, data, Eigen::VectorXd::Constant(1, q));
      EnergyTerms e;
      stored_energy(model, data, Eigen::VectorXd::Constant(1, w), Eigen::VectorXd::Constant(1, i), e);
      CAPTURE(std::string(to_string(motor)));
      CAPTURE(q);
      // Rounding only: 1e-14 relative (1e-15 J absolute where the term is zero).
      CHECK(approx(e.kinetic_links, 0.5 * (I + m * lc * lc) * w * w, 1e-15, 1e-14));
      CHECK(approx(e.potential, m * g * (z0 + lc * std::sin(q)), 1e-15, 1e-14));
      const double jm = motor == MotorModel::none ? 0.0 : 5e-7 * 50 * 50;
      CHECK(approx(e.kinetic_rotors, 0.5 * jm * w * w, 1e-15, 1e-14));
      CHECK(approx(e.magnetic, motor == MotorModel::full ? 0.5 * 0.5e-3 * i * i : 0.0, 1e-15, 1e-14));
    }
  }
  // Without gravity there is no potential energy at all.
  Model weightless = planar_arm({{l, m, lc, I}});
  weightless.effects.gravity = false;
  finalize(weightless);
  Data data(weightless);
  forward_kinematics(weightless, data, Eigen::VectorXd::Constant(1, 0.7));
  EnergyTerms e;
  stored_energy(weightless, data, Eigen::VectorXd::Constant(1, 1.0), data.current, e);
  CHECK(e.potential == 0.0);
}

TEST_CASE("balance_residual: supplied - lost - change of stored energy, each term with its sign") {
  // Sources: E_in, normal work, projection, hand force. Sinks: Joule, viscous,
  // friction, impacts. Stored: links, rotors, potential, magnetic. Values chosen so that
  // every term has a different power of two: the sum is exact in floating point.
  EnergyTerms initial;
  initial.kinetic_links = 1, initial.kinetic_rotors = 2, initial.potential = 4, initial.magnetic = 8;
  EnergyTerms now = initial;
  now.electrical_in = 1024, now.normal_work = 512, now.projection = 256, now.external = 128;
  now.joule = 64, now.viscous = 32, now.friction = 16, now.impact_loss = 2048;
  now.kinetic_links = 4096, now.potential = 8192;
  CHECK(balance_residual(now, initial) ==
        (1024.0 + 512 + 256 + 128) - (64.0 + 32 + 16 + 2048) - ((4096.0 - 1) + (8192.0 - 4)));
  CHECK(balance_residual(initial, initial) == 0.0);
}

TEST_CASE("energy drawn and regenerated: drawn - regenerated = E_in at every sample; braking motors regenerate") {
  // The arm is swung by voltage profiles and falls back: the motors drive it
  // up, then brake it on the way down (v i < 0).
  const RunResult r = simulate(driven_arm(IntegratorKind::rk4, 1e-3, 2.0, 0.5e-3), {});
  REQUIRE(r.valid);
  const Recording& t = r.trajectory;
  const int in = t.column("E_in"), drawn = t.column("E_drawn"), regen = t.column("E_regenerated");
  REQUIRE(drawn >= 0);
  REQUIRE(regen >= 0);
  double worst = 0;
  for (std::size_t row = 0; row < t.rows(); ++row) {
    // The three integrands add up exactly at every stage (max(p,0) - max(-p,0) = p),
    // so the integrals agree to rounding.
    const double gap = t.at(row, drawn) - t.at(row, regen) - t.at(row, in);
    worst = std::max(worst, std::abs(gap) / std::max(t.at(row, drawn), 1e-300));
    CHECK(t.at(row, regen) >= 0);
  }
  MESSAGE("drawn ", r.energy_final.drawn, " J, regenerated ", r.energy_final.regenerated,
          " J, E_in ", r.energy_final.electrical_in, " J; worst |drawn - regen - E_in| / drawn = ", worst);
  CHECK(worst < 1e-12);
  CHECK(r.energy_final.regenerated > 0);
  CHECK(r.energy_final.drawn > r.energy_final.electrical_in);
  CHECK(r.metrics["energy_drawn"] == r.energy_final.drawn);
  CHECK(r.metrics["energy_regenerated"] == r.energy_final.regenerated);
}

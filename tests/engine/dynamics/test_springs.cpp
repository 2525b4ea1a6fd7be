// engine/dynamics/springs.hpp: joint springs (a counterbalance) against closed
// forms: a preloaded spring holds a link against gravity at its angle under
// every dynamics method, a spring alone swings a link at sqrt(k / I), and the
// energy balance closes with the springs' potential among the stored terms.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/dynamics/forward_dynamics.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/dynamics/springs.hpp"
#include "engine/run/simulator.hpp"
#include "support/models.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// One link, 1 kg, its com 0.15 m out, 0.01 kg m^2 about it: I = 0.0325 kg m^2
// about the joint; its gravity torque at q is m g l_c cos q (q up from horizontal).
constexpr double kMass = 1.0, kCom = 0.15, kInertia = 0.01 + kMass * kCom * kCom, kG = 9.81;

Model one_link(double q0) {
  Model m = planar_arm({{0.3, kMass, kCom, 0.01}});
  m.initial.q = Eigen::VectorXd::Constant(1, q0);
  return m;
}

}  // namespace

TEST_CASE("joint springs: a spring preloaded with the gravity torque holds a link at rest; off that angle qdd = (tau_s - m g l_c cos q) / I, for every dynamics method") {
  const double q0 = 0.4, k = 3.0;
  Model m = one_link(q0);
  m.springs = {{0, kMass * kG * kCom * std::cos(q0), k, q0}};
  finalize(m);
  for (DynamicsMethod method : {DynamicsMethod::crba, DynamicsMethod::aba, DynamicsMethod::walker_orin}) {
    CAPTURE(static_cast<int>(method));
    Data data(m);
    Eigen::VectorXd qdd(1);
    forward_kinematics(m, data, m.initial.q);
    forward_dynamics(m, data, method, data.zero, data.zero, qdd);
    CHECK(std::abs(qdd[0]) < 1e-12);  // g from 9.81 and cos: round-off of ~1.5 N m / 0.0325
    const double q = q0 + 0.1;
    forward_kinematics(m, data, Eigen::VectorXd::Constant(1, q));
    forward_dynamics(m, data, method, data.zero, data.zero, qdd);
    const double expected = (kMass * kG * kCom * std::cos(q0) - k * 0.1 - kMass * kG * kCom * std::cos(q)) / kInertia;
    CHECK(qdd[0] == doctest::Approx(expected).epsilon(1e-12));
  }
  // Inverse dynamics asks the motor for what the spring leaves: none at q0.
  Data data(m);
  forward_kinematics(m, data, m.initial.q);
  Eigen::VectorXd tau(1);
  inverse_dynamics(m, data, data.zero, data.zero, {}, tau);
  CHECK(std::abs(tau[0]) < 1e-14);
  inverse_dynamics(m, data, data.zero, data.zero, {true, true, true, false}, tau);
  CHECK(tau[0] == doctest::Approx(kMass * kG * kCom * std::cos(q0)).epsilon(1e-14));
}

TEST_CASE("joint springs: a spring alone swings a link as q(t) = at + (q0 - at) cos(sqrt(k / I) t); the balance closes with E_spring stored") {
  const double at = 0.2, q0 = 0.3, k = 2.0, torque = 0.5;
  Model m = one_link(q0);
  m.effects.gravity = false;
  // A preload moves the spring's equilibrium to at + torque / k.
  m.springs = {{0, torque, k, at}};
  m.options = {1.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  const RunResult r = simulate(m, {});
  const double omega = std::sqrt(k / kInertia), rest = at + torque / k;
  const int q_column = r.trajectory.column("q0"), spring_column = r.trajectory.column("E_spring");
  REQUIRE(q_column >= 0);
  REQUIRE(spring_column >= 0);
  double worst = 0;
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row) {
    const double t = r.trajectory.at(row, 0);
    worst = std::max(worst, std::abs(r.trajectory.at(row, q_column) - (rest + (q0 - rest) * std::cos(omega * t))));
  }
  // rk4's global error ~ (omega h)^4 / 120 x amplitude 0.05 x omega t: ~1e-13 here.
  CHECK(worst < 1e-10);
  const double stretch = r.trajectory.at(r.trajectory.rows() - 1, q_column) - at;
  CHECK(r.energy_final.spring == doctest::Approx(-torque * stretch + 0.5 * k * stretch * stretch).epsilon(1e-12));
  // Kinetic plus spring energy is what the spring had at the start.
  const double start = -torque * (q0 - at) + 0.5 * k * (q0 - at) * (q0 - at);
  CHECK(r.energy_initial.spring == doctest::Approx(start).epsilon(1e-14));
  CHECK(std::abs(r.balance_residual) < 1e-12);
  CHECK(std::abs(r.energy_final.kinetic_links + r.energy_final.spring - start) < 1e-12);
}

TEST_CASE("joint springs: a motor-driven arm with springs on both joints keeps its energy balance to 1e-6 of E_in, falling with the step") {
  // The steps of test_energy.cpp's driven arm (L/R = 0.25 ms resolved).
  double previous = 0;
  for (double step : {2e-4, 1e-4}) {
    Model m = driven_arm(IntegratorKind::rk4, step, 1.0, 0.5e-3);
    m.springs = {{0, 3.0, 4.0, 0.2}, {1, -0.5, 1.5, 0.0}};
    finalize(m);
    const RunResult r = simulate(m, {});
    CHECK(r.energy_final.spring != r.energy_initial.spring);
    const double relative = std::abs(r.balance_residual) / r.energy_final.electrical_in;
    CAPTURE(step);
    CHECK(relative < 1e-6);
    if (previous > 0) CHECK(relative < previous / 4);  // rk4: ~16x for half the step
    previous = relative;
  }
}

TEST_CASE("joint springs: the model refuses a spring at a joint the arm lacks or with negative stiffness") {
  Model m = one_link(0.0);
  m.springs = {{1, 1.0, 0.0, 0.0}};
  CHECK_THROWS_WITH_AS(finalize(m), doctest::Contains("joint spring"), std::invalid_argument);
  m.springs = {{0, 1.0, -1.0, 0.0}};
  CHECK_THROWS_WITH_AS(finalize(m), doctest::Contains("stiffness >= 0"), std::invalid_argument);
}

// engine/run/derivative.cpp: the right-hand side x' = lambda .* x + N(t, x): the stiff
// rates, and N of analytic states (a pendulum, motors, a hand force) with its energy powers.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/run/derivative.hpp"
#include "engine/state_layout.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"
#include "support/models.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("stiff_rates: -R/L on the currents (motor: full), zero everywhere else") {
  const Model full = driven_arm(IntegratorKind::rk4, 1e-3, 1.0, 0.5e-3);
  const StateLayout s(full);
  Eigen::ArrayXd lambda = Eigen::ArrayXd::Constant(s.size, 7.0);
  stiff_rates(full, lambda);
  REQUIRE(s.current >= 0);
  for (int k = 0; k < s.size; ++k) {
    CAPTURE(k);
    const bool current = k >= s.current && k < s.current + s.n;
    CHECK(lambda[k] == (current ? -2.0 / 0.5e-3 : 0.0));  // small_servo: R = 2 ohm
  }
  Model quasi = full;
  quasi.effects.motor = MotorModel::quasi_static;
  finalize(quasi);
  Eigen::ArrayXd none = Eigen::ArrayXd::Constant(StateLayout(quasi).size, 7.0);
  stiff_rates(quasi, none);
  CHECK((none == 0.0).all());
}

TEST_CASE("nonstiff_rates: a pendulum at rest, horizontal, has qdd = -m g lc / (I + m lc^2)") {
  // simple_pendulum: one link, m = 1 kg, com lc = 0.25 m, I = 0.02 kg m^2 about the com,
  // no motor, no damping. Rounding only: 1e-14 relative.
  const Model m = simple_pendulum(IntegratorKind::rk4, 1e-3, 1.0);
  const StateLayout s(m);
  Data data(m);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(s.size), N(s.size);
  nonstiff_rates(m, data, 0.0, x, N);
  const double expected = -1.0 * 9.81 * 0.25 / (0.02 + 1.0 * 0.25 * 0.25);
  CHECK(N[s.q()] == 0.0);  // q' = qd
  CHECK(approx(N[s.qd()], expected, 0, 1e-14));
  CHECK(approx(data.qdd[0], expected, 0, 1e-14));
  for (int k = 0; k < s.energy_terms; ++k) CHECK(N[s.energy + k] == 0.0);  // nothing flows at rest
  // Moving at qd = 2 rad/s, q' follows the state and the input power stays zero.
  x[s.qd()] = 2.0;
  nonstiff_rates(m, data, 0.0, x, N);
  CHECK(N[s.q()] == 2.0);
  CHECK(N[s.energy] == 0.0);
}

TEST_CASE("nonstiff_rates with full motors: di/dt, electrical powers and the viscous loss") {
  // lambda .* x + N on the currents is the whole electrical equation (16),
  // L di/dt = v - R i - Km qd; the powers are v.i, i^T R i and qd^T (D + Dm) qd.
  const Model m = driven_arm(IntegratorKind::rk4, 1e-3, 1.0, 0.5e-3);
  const StateLayout s(m);
  Data data(m);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(s.size), N(s.size);
  x.segment(s.q(), 2) << 0.3, -0.4;
  x.segment(s.qd(), 2) << 1.2, -0.7;
  x.segment(s.current, 2) << 0.8, -0.3;
  const double t = 0.37;
  nonstiff_rates(m, data, t, x, N);
  Eigen::ArrayXd lambda(s.size);
  stiff_rates(m, lambda);
  const Eigen::Vector2d v(m.inputs.joints[0].at(t), m.inputs.joints[1].at(t));  // below 24 V
  const Eigen::Vector2d i = x.segment(s.current, 2), qd = x.segment(s.qd(), 2);
  const Eigen::Vector2d di = (v - m.resistance.cwiseProduct(i) - m.km.cwiseProduct(qd)).cwiseQuotient(m.inductance);
  const Eigen::VectorXd full = lambda.matrix().cwiseProduct(x) + N;
  // Rates of order 1e4 A/s from differences of volts: 1e-12 relative.
  CHECK(approx(full.segment(s.current, 2), di, 0, 1e-12));
  CHECK(approx(data.current_rate, di, 0, 1e-12));
  CHECK(approx(N[s.energy], v.dot(i), 1e-15, 1e-14));
  CHECK(approx(N[s.energy + 1], i.dot(m.resistance.cwiseProduct(i)), 1e-15, 1e-14));
  CHECK(approx(N[s.energy + 2], qd.dot(m.viscous.cwiseProduct(qd)), 1e-15, 1e-14));
  CHECK(approx(data.actuation, Eigen::Vector2d(m.km.cwiseProduct(i)), 1e-15, 1e-14));
}

TEST_CASE("nonstiff_rates with a hand force: J^T F on the joints, F.v its own integral, not E_in") {
  // The horizontal pendulum (tip 0.5 m out) with an upward hand force f = m g lc / l is
  // held: qdd = 0. Turning at qd, the force's power is f l qd (the tip moves up at l qd).
  Model m = simple_pendulum(IntegratorKind::rk4, 1e-3, 1.0);
  const double f = 1.0 * 9.81 * 0.25 / 0.5;
  m.hand_load.force = Eigen::Vector3d(0, 0, f);
  finalize(m);
  const StateLayout s(m);
  REQUIRE(s.slot(Energy::external) >= 0);
  Data data(m);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(s.size), N(s.size);
  nonstiff_rates(m, data, 0.0, x, N);
  CHECK(std::abs(N[s.qd()]) < 1e-14);  // held: gravity torque 2.4525 N m balanced
  x[s.qd()] = 1.5;
  nonstiff_rates(m, data, 0.0, x, N);
  CHECK(approx(N[s.slot(Energy::external)], f * 0.5 * 1.5, 0, 1e-14));
  CHECK(std::abs(N[s.energy]) < 1e-14);  // no input torques: E_in does not count the force
}

TEST_CASE("a derivative evaluation allocates nothing: s = 2..60, p = 0..4 resting elbows, every solver") {
  // Random chains with full motors and p elbows resting on random planes: forward
  // dynamics (p = 0), the Schur path and the aba path. Counted: the C allocator
  // (Eigen allocates there, unseen by operator new) and operator new.
  for (int n : {2, 7, 15, 30, 60}) {
    for (int p : {0, 1, 2, 4}) {
      for (ConstraintSolver solver : {ConstraintSolver::schur, ConstraintSolver::aba}) {
        CAPTURE(n);
        CAPTURE(p);
        CAPTURE(std::string(to_string(solver)));
        Model m = random_chain(n, static_cast<std::uint32_t>(300 + n));
        for (int k = 0; k < p; ++k)
          m.elbows.push_back({'e' + std::to_string(k), (k + 1) * (n - 1) / p, Eigen::Vector3d(0.1, 0, 0), 0.03});
        m.table = {TableBox{}};
        m.effects.contact = true;
        m.contact.solver = solver;
        finalize(m);
        Data data(m);
        const StateLayout s(m);
        Eigen::VectorXd x = Eigen::VectorXd::Random(s.size), out = Eigen::VectorXd::Zero(s.size);
        for (int k = 0; k < p; ++k) {
          data.contact.active.push_back(k);
          data.contact.normal[static_cast<std::size_t>(k)] = Eigen::Vector3d::Random().normalized();
        }
        const long mallocs = malloc_count(), news = allocation_count();
        for (int r = 0; r < 3; ++r) nonstiff_rates(m, data, 0.0, x, out);
        CHECK(malloc_count() - mallocs == 0);
        CHECK(allocation_count() - news == 0);
        CHECK(out.allFinite());
      }
    }
  }
}

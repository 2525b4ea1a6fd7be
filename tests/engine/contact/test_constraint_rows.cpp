// engine/contact/constraint_rows.cpp: the rows of M* for resting elbows (eq. 6-9, 15,
// 31) against finite differences of the constraint C(q) = n.(c(q) - s) - r, Baumgarte's
// terms, and sliding friction (directly, and a spinning rod slowing down as mu f_n says).
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "engine/run/simulator.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// C_k(q) of elbow k for a fixed table normal n and surface point s.
double constraint_at(const Model& m, Data& data, const Eigen::VectorXd& q, int k) {
  const Elbow& e = m.elbows[k];
  forward_kinematics(m, data, q);
  return data.contact.normal[k].dot(point_position(data, e.link, e.point) - data.contact.surface[k]) -
         e.radius;
}

Model without_stabilization(Model m) {
  m.effects.stabilization = Stabilization::none;
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("constraint_rows: C, Jc = dC/dq, Cd = Jc qd and gamma = -d2C/dt2 (qdd = 0) by differences") {
  for (int p = 1; p <= 3; ++p) {
    CAPTURE(p);
    const Model m = without_stabilization(chain_with_elbows(6, p, 700 + p));
    Data data(m);
    const Eigen::VectorXd q = 2 * Eigen::VectorXd::Random(6), qd = Eigen::VectorXd::Random(6);
    forward_kinematics(m, data, q);
    set_random_contacts(m, data);
    constraint_rows(m, data, qd);
    const ContactData& c = data.contact;
    REQUIRE(c.Jc.rows() == p);
    REQUIRE(c.rows() == p);
    for (int r = 0; r < p; ++r) {
      const int k = c.active[r];
      CAPTURE(r);
      Data scratch(m);
      scratch.contact.normal = c.normal;
      scratch.contact.surface = c.surface;
      const auto C = [&](const Eigen::VectorXd& at) { return constraint_at(m, scratch, at, k); };
      CHECK(approx(c.C[r], C(q), 1e-15));
      // Central differences, h = 1e-6: truncation ~h^2, roundoff ~1e-16/h: 1e-8.
      Eigen::RowVectorXd grad(6);
      for (int j = 0; j < 6; ++j) {
        Eigen::VectorXd up = q, down = q;
        up[j] += 1e-6;
        down[j] -= 1e-6;
        grad[j] = (C(up) - C(down)) / 2e-6;
      }
      CHECK(approx(c.Jc.row(r), grad, 1e-8));
      CHECK(c.Cd[r] == c.Jc.row(r).dot(qd));
      // Along q(t) = q + t qd, d2C/dt2 = n^T Jdot qd. Second differences with h = 1e-4:
      // truncation ~h^2, roundoff ~1e-16/h^2: 1e-6.
      const double h = 1e-4;
      const double d2C = (C(q + h * qd) - 2 * C(q) + C(q - h * qd)) / (h * h);
      CHECK(approx(c.gamma[r], -d2C, 1e-6));
      CHECK(c.Jf.row(r) == c.Jc.row(r));  // no friction: the force acts along the row
    }
  }
}

TEST_CASE("constraint_rows: Baumgarte adds -(2/T) Cd - C/T^2 to gamma, T = baumgarte_time") {
  const Model none = without_stabilization(chain_with_elbows(5, 2, 711));
  Model baumgarte = none;
  baumgarte.effects.stabilization = Stabilization::baumgarte;
  baumgarte.contact.baumgarte_time = 0.02;
  finalize(baumgarte);
  Data a(none), b(baumgarte);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(5), qd = Eigen::VectorXd::Random(5);
  forward_kinematics(none, a, q);
  set_random_contacts(none, a);
  forward_kinematics(baumgarte, b, q);
  b.contact.active = a.contact.active;
  b.contact.normal = a.contact.normal;
  b.contact.surface = a.contact.surface;
  constraint_rows(none, a, qd);
  constraint_rows(baumgarte, b, qd);
  const double T = 0.02;
  for (int r = 0; r < 2; ++r) {
    CHECK(b.contact.C[r] == a.contact.C[r]);
    // The same terms in another order: rounding, 1e-12 relative to the largest.
    const double expected = a.contact.gamma[r] - 2 / T * a.contact.Cd[r] - a.contact.C[r] / (T * T);
    CHECK(approx(b.contact.gamma[r], expected, 1e-12 * std::abs(a.contact.C[r] / (T * T))));
  }
}

TEST_CASE("constraint_rows: friction row Jf = Jc - mu s^T J_p, so Jf qd = Cd - mu |v_t| scale(|v_t|) when sliding") {
  // s is the sliding direction of the contact point (sphere centre - r n) times
  // the law's scale: v / max(v, slip_velocity) (saturated), tanh(v / tanh_velocity)
  // (tanh). Both sit in the row of M* with f_n (not lagged a step).
  for (const FrictionLaw law : {FrictionLaw::saturated, FrictionLaw::tanh}) {
    CAPTURE(to_string(law));
    Model m = without_stabilization(chain_with_elbows(5, 1, 721));
    m.effects.friction = true;
    m.contact.friction.mu = 0.4;
    m.contact.friction.law = law;
    finalize(m);
    Data data(m);
    const Eigen::VectorXd q = Eigen::VectorXd::Random(5), fast = Eigen::VectorXd::Random(5);
    forward_kinematics(m, data, q);
    set_random_contacts(m, data);
    const Elbow& e = m.elbows[0];
    const Eigen::Vector3d n = data.contact.normal[0];
    const Eigen::Vector3d contact = point_position(data, e.link, e.point) - e.radius * n;
    const Eigen::Vector3d local = data.rotation[e.link].transpose() * (contact - data.origin[e.link]);
    const FrictionOptions& f = m.contact.friction;
    for (const double scale : {1.0, 1e-6}) {
      const Eigen::VectorXd qd = scale * fast;
      const Eigen::Vector3d v = point_velocity(data, e.link, local, qd);
      const double slide = (v - n * n.dot(v)).norm();
      CAPTURE(slide);
      constraint_rows(m, data, qd);
      CHECK(approx(data.contact.slide[0], slide, 1e-15, 1e-12));
      const double along = law == FrictionLaw::tanh ? slide * std::tanh(slide / f.tanh_velocity)
                           : slide >= f.slip_velocity ? slide
                                                      : slide * slide / f.slip_velocity;
      // Rounding of sums of O(1) terms scaled by qd: 1e-12 relative to |qd|.
      CHECK(approx(data.contact.Jf.row(0).dot(qd), data.contact.Cd[0] - 0.4 * along, 1e-12 * scale));
    }
    REQUIRE(1e-6 * fast.norm() < std::min(f.slip_velocity, f.tanh_velocity));  // the second case is below both
  }
}

TEST_CASE("friction: a sliding elbow decelerates as mu f_n predicts") {
  const SpinningRod rod;
  const RunResult r = simulate(rod.model(0.15), {});
  REQUIRE(r.completed);
  const double alpha = rod.mu * rod.normal_force() * rod.length / rod.yaw_inertia();
  const double expected = rod.omega0 - alpha * 0.15;
  MESSAGE("yaw rate at 0.15 s: ", last(r, "qd0"), " rad/s, predicted ", expected);
  CHECK(last(r, "qd0") == doctest::Approx(expected).epsilon(1e-6));
  CHECK(last(r, "fn_tip") == doctest::Approx(rod.normal_force()).epsilon(1e-6));
  // The energy lost to sliding is the kinetic energy the spin lost.
  CHECK(std::abs(r.balance_residual) < 1e-8);
  CHECK(r.energy_final.friction > 0.1);
}

TEST_CASE("constraint_rows calls the C allocator zero times, with and without friction") {
  for (bool friction : {false, true}) {
    Model m = chain_with_elbows(5, 2, 731);
    m.effects.friction = friction;
    m.contact.friction.mu = 0.4;
    finalize(m);
    Data data(m);
    const Eigen::VectorXd q = Eigen::VectorXd::Random(5), qd = Eigen::VectorXd::Random(5);
    forward_kinematics(m, data, q);
    set_random_contacts(m, data);
    constraint_rows(m, data, qd);  // the first call may size the rows (use_rows)
    const long mallocs = malloc_count();
    constraint_rows(m, data, qd);
    const long calls = malloc_count() - mallocs;
    CAPTURE(friction);
    CHECK(calls == 0);
  }
}

TEST_CASE("constraint_rows: the link rates bias_torques left are used only at their state") {
  // After bias_torques() at the same kinematics and qd the rows read its outward
  // pass (no sweep of their own): the same rows to rounding. At another qd, or
  // after the kinematics moved on, they must sweep afresh: bit for bit the rows
  // of a Data that never ran bias_torques.
  const Model m = chain_with_elbows(9, 3, 811);
  const Eigen::VectorXd q = 2 * Eigen::VectorXd::Random(9), q2 = 2 * Eigen::VectorXd::Random(9);
  const Eigen::VectorXd qd = Eigen::VectorXd::Random(9), qd2 = Eigen::VectorXd::Random(9);
  const auto fresh = [&](const Eigen::VectorXd& at_q, const Eigen::VectorXd& at_qd, Data& like) {
    Data d(m);
    forward_kinematics(m, d, at_q);
    d.contact.active = like.contact.active;
    d.contact.resting = like.contact.resting;
    d.contact.normal = like.contact.normal;
    d.contact.surface = like.contact.surface;
    d.contact.detected = like.contact.detected;
    d.contact.feature = like.contact.feature;
    constraint_rows(m, d, at_qd);
    return Eigen::VectorXd(d.contact.gamma);
  };
  Data data(m);
  forward_kinematics(m, data, q);
  set_random_contacts(m, data);
  bias_torques(m, data, qd);
  constraint_rows(m, data, qd);
  CHECK(data.contact.rates_in_data);
  const Eigen::VectorXd expected = fresh(q, qd, data);
  const double scale = expected.cwiseAbs().maxCoeff();
  CHECK(approx(Eigen::VectorXd(data.contact.gamma), expected, 1e-12 * scale));
  constraint_rows(m, data, qd2);  // other rates
  CHECK_FALSE(data.contact.rates_in_data);
  CHECK(approx(Eigen::VectorXd(data.contact.gamma), fresh(q, qd2, data), 0.0));
  bias_torques(m, data, qd);
  forward_kinematics(m, data, q2);  // other kinematics, same rates
  constraint_rows(m, data, qd);
  CHECK_FALSE(data.contact.rates_in_data);
  CHECK(approx(Eigen::VectorXd(data.contact.gamma), fresh(q2, qd, data), 0.0));
}

// Elbows on the table through whole runs: drift control, release and landing
// times, impacts, dependent rows, friction and Painleve's paradox.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/collision.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/contact/impact.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

const ContactEvent* first_event(const RunResult& r, ContactEvent::Kind kind) {
  for (const ContactEvent& e : r.events)
    if (e.kind == kind) return &e;
  return nullptr;
}

double last(const RunResult& r, const std::string& column) {
  return r.trajectory.at(r.trajectory.rows() - 1, r.trajectory.column(column));
}

// The elbow arm released from `lift` rad above its resting pose, unactuated.
Model falling_arm(double lift, EventTiming events, double step, double restitution) {
  const ElbowArm arm;
  Model m = arm.model(0.0, 0.0);
  m.inputs.joints.clear();
  m.initial.q[0] += lift;
  m.contact.events = events;
  m.contact.restitution = restitution;
  m.contact.locate_tolerance = 1e-12;
  m.options = {0.6, step, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

}  // namespace

TEST_CASE("drift over 10 s of sliding: projection < 1e-10 m, Baumgarte < 1e-6 m, none drifts") {
  double drift[3], drift_at_1s = 0;
  for (Stabilization s : {Stabilization::none, Stabilization::baumgarte, Stabilization::projection}) {
    const RunResult r = simulate(sliding_arm(s, 10.0, 1e-3), RunOptions{100, {}});
    REQUIRE(r.completed);
    CHECK(first_event(r, ContactEvent::Kind::release) == nullptr);  // the elbow stays down
    CHECK(std::abs(last(r, "q0") - r.trajectory.at(0, 1)) > 0.3);  // while the arm moves
    drift[int(s)] = r.contact.max_abs_C;
    if (s == Stabilization::none) drift_at_1s = std::abs(r.trajectory.at(10, r.trajectory.column("d_elbow")));
    MESSAGE(std::string(to_string(s)), ": max |C| = ", r.contact.max_abs_C, " m, max |Jc qd| = ",
            r.contact.max_abs_Cd, " m/s, |balance residual| = ", std::abs(r.balance_residual), " J");
  }
  CHECK(drift[int(Stabilization::projection)] < 1e-10);
  CHECK(drift[int(Stabilization::baumgarte)] < 1e-6);
  // Without control the error of C(q) = 0 accumulates: it grows with time
  // and ends above Baumgarte's bound.
  MESSAGE("none: |C| at 1 s = ", drift_at_1s, " m");
  CHECK(drift[int(Stabilization::none)] > 5 * drift_at_1s);
  CHECK(drift[int(Stabilization::none)] > drift[int(Stabilization::baumgarte)]);
}

TEST_CASE("release: the elbow leaves when its force reaches zero (locate: within 1e-6 s)") {
  // tau1 = G1/2 + G1 t: the statics force (G1 - tau1)/(l1 cos q1) is zero at t* = 0.5 s.
  const ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), arm.G1());
  m.contact.events = EventTiming::locate;
  m.contact.locate_tolerance = 1e-10;
  finalize(m);
  const RunResult located = simulate(m, {});
  REQUIRE(located.completed);
  const ContactEvent* e = first_event(located, ContactEvent::Kind::release);
  REQUIRE(e != nullptr);
  MESSAGE("release located at ", e->t, " s (analytic 0.5 s)");
  CHECK(std::abs(e->t - 0.5) < 1e-6);
  m.contact.events = EventTiming::step;
  finalize(m);
  const ContactEvent* s = first_event(simulate(m, {}), ContactEvent::Kind::release);
  REQUIRE(s != nullptr);
  CHECK(s->t >= 0.5 - 1e-12);
  CHECK(s->t <= 0.5 + 1e-3 + 1e-12);  // at the first step boundary after it
}

TEST_CASE("landing: located landing time matches a fine reference within 1e-6 s; plastic impact") {
  const RunResult coarse = simulate(falling_arm(0.15, EventTiming::locate, 1e-3, 0.0), {});
  const RunResult fine = simulate(falling_arm(0.15, EventTiming::locate, 1e-4, 0.0), {});
  const RunResult stepped = simulate(falling_arm(0.15, EventTiming::step, 1e-3, 0.0), {});
  REQUIRE(coarse.completed);
  const ContactEvent* a = first_event(coarse, ContactEvent::Kind::landing);
  const ContactEvent* b = first_event(fine, ContactEvent::Kind::landing);
  const ContactEvent* c = first_event(stepped, ContactEvent::Kind::landing);
  REQUIRE(a != nullptr);
  REQUIRE(b != nullptr);
  REQUIRE(c != nullptr);
  MESSAGE("landing at ", a->t, " s (step 1e-3, locate), ", b->t, " s (step 1e-4), ", c->t,
          " s (step mode); speed ", a->speed, " m/s, impulse ", a->impulse, " N s");
  CHECK(std::abs(a->t - b->t) < 1e-6);
  CHECK(c->t >= a->t);
  CHECK(c->t < a->t + 1e-3 + 1e-9);
  CHECK(a->speed > 0.1);
  CHECK(a->impulse > 0);
  CHECK(coarse.energy_final.impact_loss == doctest::Approx(a->energy_lost).epsilon(1e-9));
  // The energy account closes with the impact loss in it.
  CHECK(std::abs(coarse.balance_residual) < 1e-6 * coarse.energy_final.impact_loss);
}

TEST_CASE("impact: plastic leaves zero normal speed, restitution e reverses e times it; KE loss == impulse formula") {
  for (double e : {0.0, 0.5}) {
    Model m = falling_arm(0.0, EventTiming::step, 1e-3, e);
    Data data(m);
    reset_state(m, data);
    data.x.segment(2, 2) = Eigen::Vector2d(-1.0, 0.7);  // elbow moving down
    forward_kinematics(m, data, data.x.head(2));
    const ImpactResult r = apply_impact(m, data, {0}, {});
    REQUIRE(r.solved);
    CAPTURE(e);
    CHECK(r.speed_before[0] < 0);
    CHECK(r.speed_after[0] == doctest::Approx(-e * r.speed_before[0]).epsilon(1e-12));
    // Delta KE = P (u- + u+) / 2; plastic: P |u-| / 2.
    CHECK(r.kinetic_before - r.kinetic_after ==
          doctest::Approx(-0.5 * r.impulse[0] * (r.speed_before[0] + r.speed_after[0])).epsilon(1e-12));
    if (e == 0.0)
      CHECK(r.kinetic_before - r.kinetic_after ==
            doctest::Approx(0.5 * r.impulse[0] * -r.speed_before[0]).epsilon(1e-12));
  }
}

TEST_CASE("dependent rows: two elbows 1e-9 m apart, and an over-constrained arm: finite forces, a warning") {
  const ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), 0.0);
  m.elbows.push_back({"twin", 0, Eigen::Vector3d(arm.l1 - 1e-9, 0, 0), arm.r});
  finalize(m);
  const RunResult twin = simulate(m, {});
  REQUIRE(twin.completed);
  REQUIRE(twin.warnings.size() >= 1);
  CHECK(twin.warnings[0].find("dependent") != std::string::npos);
  const double total = last(twin, "fn_elbow") + last(twin, "fn_twin");
  CHECK(total == doctest::Approx(arm.statics_force(0.5 * arm.G1())).epsilon(1e-6));
  for (double v : twin.trajectory.values) CHECK(std::isfinite(v));

  // Flat on the table: three elbows on a 2-dof arm (rank 2 < 3 rows).
  Model flat = planar_arm({{0.4, 1.3, 0.2, 0.02}, {0.35, 0.9, 0.175, 0.01}});
  flat.elbows = {{"a", 0, Eigen::Vector3d(0.15, 0, 0), 0.03}, {"b", 0, Eigen::Vector3d(0.4, 0, 0), 0.03},
                 {"c", 1, Eigen::Vector3d(0.3, 0, 0), 0.03}};
  TableBox top;
  top.size = Eigen::Vector3d(2, 1, 0.1);
  top.center = Eigen::Vector3d(0.5, 0, -0.03 - 0.05);
  flat.table = {top};
  flat.effects.contact = true;
  flat.options = {0.5, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(flat);
  const RunResult over = simulate(flat, {});
  REQUIRE(over.completed);
  REQUIRE_FALSE(over.warnings.empty());
  CHECK(over.warnings[0].find("dependent") != std::string::npos);
  for (double v : over.trajectory.values) CHECK(std::isfinite(v));
  CHECK(std::abs(last(over, "qd0")) < 1e-9);  // it lies still
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

TEST_CASE("friction: high mu in a Painleve configuration stops with a clear message") {
  Model m = sliding_arm(Stabilization::baumgarte, 0.2, 1e-3);
  m.effects.friction = true;
  m.contact.friction = 1.0;
  finalize(m);
  Data data(m);
  reset_state(m, data);
  const Eigen::VectorXd q = m.initial.q;
  forward_kinematics(m, data, q);
  data.contact.active = {0};
  data.contact.normal[0] = Eigen::Vector3d::UnitZ();
  // A sliding motion that keeps the elbow on the table: qd in the null space of Jc.
  Eigen::VectorXd qd = Eigen::Vector3d(1, 0, 0);
  constraint_rows(m, data, qd);
  const Eigen::RowVectorXd Jc = data.contact.Jc.row(0);
  qd -= Jc.transpose() * (Jc * qd) / Jc.squaredNorm();
  constraint_rows(m, data, qd);
  mass_matrix_crba(m, data);
  data.llt.compute(data.mass_matrix);
  const Eigen::RowVectorXd Jt = data.contact.Jc.row(0) - data.contact.Jf.row(0);  // mu = 1
  const double A = Jc * data.llt.solve(Jc.transpose());
  double B = Jc * data.llt.solve(Jt.transpose());
  if (B < 0) qd = -qd, B = -B;  // slide the way friction pushes the elbow down
  REQUIRE(B > 0);
  m.contact.friction = 3.0 * A / B;
  m.initial.qd = qd;
  finalize(m);
  const RunResult r = simulate(m, {});
  CHECK_FALSE(r.completed);
  MESSAGE(r.failure);
  CHECK(r.failure.find("Painleve") != std::string::npos);
  CHECK(r.failure.find("t = 0") != std::string::npos);
}

TEST_CASE("a scene with contact off never builds the collision world") {
  const long before = CollisionWorld::worlds_built();
  const RunResult off = simulate(pendulum(IntegratorKind::rk4, 1e-3, 0.1), {});
  CHECK(off.collision_worlds_built == 0);
  CHECK(CollisionWorld::worlds_built() == before);
  const ElbowArm arm;
  const RunResult on = simulate(arm.model(0.5 * arm.G1(), 0.0), {});
  CHECK(on.collision_worlds_built == 1);
}

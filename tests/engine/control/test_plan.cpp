// engine/control/plan.cpp: the plan (IK samples on the step, central differences, the
// feed-forward voltages) and the controller built on it; errors for tasks that cannot be
// followed; force control through the plan's commanded elbow force.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/control/plan.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The writing arm's line task, shortened (0.3 s run, 0.2 s delay, 0.5 s task) so that
// the plan has 301 samples.
ExperimentScene short_scene(bool elbow_on, MotorModel motor) {
  WritingArm arm;
  arm.elbow_on = elbow_on;
  arm.task_duration = 0.5;
  arm.run_duration = 0.3;
  ExperimentScene s = arm.scene();
  s.model.effects.motor = motor;
  finalize(s.model);
  return s;
}

}  // namespace

TEST_CASE("IK: an unreachable target is a clear error with the time and the distance missed") {
  WritingArm arm;
  auto [m, x] = arm.scene();
  x.task.points[1] = x.task.points[0] + Eigen::Vector3d(1.0, 0, 0);  // 1 m further: out of reach
  try {
    make_plan(m, x);
    FAIL("no error");
  } catch (const PlanError& e) {
    const std::string msg = e.what();
    MESSAGE(msg);
    CHECK(msg.find("out of reach") != std::string::npos);
    CHECK(msg.find("at t = ") != std::string::npos);
    CHECK(msg.find("missed by ") != std::string::npos);
  }
}

TEST_CASE("force control holds the commanded elbow force in a quasi-static motion") {
  WritingArm arm;
  arm.controller = ControllerSpec::Kind::force;
  auto [m, x] = arm.scene();
  for (double desired : {2.0, 5.0, 10.0}) {
    x.controller.desired_force = desired;
    const RunResult r = simulate(m, x, RunOptions{10, {}});
    REQUIRE(r.completed);
    CAPTURE(desired);
    // The band: 1 % of the command. The estimate comes from the algebraic
    // relation of M* with the exact model, so only tracking errors remain.
    CHECK(r.metrics["elbow_force_min"] > 0.99 * desired);
    CHECK(r.metrics["elbow_force_max"] < 1.01 * desired);
    CHECK(r.metrics["time_in_contact"] == doctest::Approx(m.options.duration));
  }
}

TEST_CASE("Plan::at and hand_at: linear between samples, clamped to the ends") {
  Plan plan;
  plan.dt = 0.5;
  plan.q = {Eigen::Vector2d(0, 1), Eigen::Vector2d(2, -1), Eigen::Vector2d(4, 3)};
  plan.hand = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 5)};
  Eigen::VectorXd out(2);
  plan.at(plan.q, 0.5, out);  // on a sample
  CHECK(out == Eigen::Vector2d(2, -1));
  plan.at(plan.q, 0.25, out);  // half way: exact in binary
  CHECK(out == Eigen::Vector2d(1, 0));
  plan.at(plan.q, 0.875, out);
  CHECK(out == Eigen::Vector2d(3.5, 2));
  plan.at(plan.q, 1.0, out);  // the last sample
  CHECK(out == Eigen::Vector2d(4, 3));
  plan.at(plan.q, 7.0, out);  // clamped
  CHECK(out == Eigen::Vector2d(4, 3));
  plan.at(plan.q, -1.0, out);
  CHECK(out == Eigen::Vector2d(0, 1));
  CHECK(plan.hand_at(0.25) == Eigen::Vector3d(0.5, 1, 1.5));
  CHECK(plan.hand_at(0.75) == Eigen::Vector3d(1, 2, 4));
  CHECK(plan.hand_at(3.0) == Eigen::Vector3d(1, 2, 5));
  CHECK(plan.hand_at(-3.0) == Eigen::Vector3d(0, 0, 0));
}

TEST_CASE("make_plan: a sample per step; qd, qdd central differences of q, zero at the ends") {
  const ExperimentScene s = short_scene(false, MotorModel::full);
  const auto plan = make_plan(s.model, s.experiment);
  const std::size_t N = plan->q.size();
  CHECK(N == 301);
  CHECK(plan->dt == s.model.options.step);
  REQUIRE(plan->qd.size() == N);
  REQUIRE(plan->qdd.size() == N);
  const double h = plan->dt;
  for (std::size_t k = 1; k + 1 < N; k += 37) {
    CAPTURE(k);
    CHECK(plan->qd[k] == (plan->q[k + 1] - plan->q[k - 1]) / (2 * h));
    CHECK(plan->qdd[k] == (plan->q[k + 1] - 2 * plan->q[k] + plan->q[k - 1]) / (h * h));
  }
  CHECK(plan->qd.front().isZero());
  CHECK(plan->qd.back().isZero());
  CHECK(plan->qdd.back().isZero());
  // The task starts after its 0.2 s delay: before it, the plan holds still up to
  // the null-space drift toward the posture (posture_weight 0.1 per sample: 5e-8
  // rad over these 100 samples; the hand itself does not move).
  CHECK((plan->q[100] - plan->q[0]).norm() < 1e-6);
  CHECK((plan->q[300] - plan->q[0]).norm() > 1e-3);
}

TEST_CASE("make_plan: v_ff = R i + Km qd_d + L di/dt, i = INV(q_d, qd_d, qdd_d) / Km (elbow off)") {
  const ExperimentScene s = short_scene(false, MotorModel::full);
  const Model& m = s.model;
  const auto plan = make_plan(m, s.experiment);
  Data data(m);
  const auto current = [&](std::size_t k) {
    forward_kinematics(m, data, plan->q[k]);
    Eigen::VectorXd tau(m.dof);
    inverse_dynamics(m, data, plan->qd[k], plan->qdd[k], InverseDynamicsTerms{}, tau);
    return Eigen::VectorXd(tau.cwiseQuotient(m.km));
  };
  for (std::size_t k = 150; k < 300; k += 49) {
    CAPTURE(k);
    const Eigen::VectorXd expected = m.resistance.cwiseProduct(current(k)) + m.km.cwiseProduct(plan->qd[k]) +
                                     m.inductance.cwiseProduct(current(k + 1) - current(k - 1)) / (2 * plan->dt);
    // The same computation: rounding, 1e-12 V.
    CHECK(elbowsim::testing::approx(plan->v_ff[k], expected, 1e-12));
  }
  CHECK(plan->f_ff[150].size() == 0);  // no elbow on the table
  CHECK(plan->resting.empty());
}

TEST_CASE("make_plan with the elbow resting: the table takes the force minimising |tau|, f >= 0") {
  // Quasi-static motors, so i = (v_ff - Km qd_d) / R gives back the planned torques.
  // Least squares over f >= 0 with f > 0: the torques left are orthogonal to the row,
  // Jc tau = 0, and tau + Jc^T f = INV(q_d, qd_d, qdd_d). Rounding: 1e-9 N m.
  const ExperimentScene s = short_scene(true, MotorModel::quasi_static);
  const Model& m = s.model;
  const auto plan = make_plan(m, s.experiment);
  CHECK(plan->resting == std::vector<int>{0});
  Data data(m);
  Matrix3Xd J(3, m.dof);
  for (std::size_t k = 10; k < 300; k += 97) {
    CAPTURE(k);
    REQUIRE(plan->f_ff[k].size() == 1);
    const double f = plan->f_ff[k][0];
    CHECK(f > 0);  // the arm leans on its elbow
    const Eigen::VectorXd tau =
        m.km.cwiseProduct((plan->v_ff[k] - m.km.cwiseProduct(plan->qd[k])).cwiseQuotient(m.resistance));
    forward_kinematics(m, data, plan->q[k]);
    const Elbow& e = m.elbows[0];
    point_jacobian(m, data, e.link, e.point, J);
    const Eigen::RowVectorXd Jc = Eigen::Vector3d::UnitZ().transpose() * J;  // flat table
    CHECK(std::abs(Jc.dot(tau)) < 1e-9 * Jc.norm());
    Eigen::VectorXd inv(m.dof);
    inverse_dynamics(m, data, plan->qd[k], plan->qdd[k], InverseDynamicsTerms{}, inv);
    CHECK(elbowsim::testing::approx(Eigen::VectorXd(tau + Jc.transpose() * f), inv, 1e-9));
  }
}

TEST_CASE("make_controller: none for an open-loop experiment, else the spec and its plan") {
  const ExperimentScene s = short_scene(false, MotorModel::full);
  CHECK(make_controller(s.model, Experiment{}) == nullptr);
  const auto controller = make_controller(s.model, s.experiment);
  REQUIRE(controller != nullptr);
  CHECK(controller->spec.kind == s.experiment.controller.kind);
  CHECK(controller->spec.kp == s.experiment.controller.kp);
  REQUIRE(controller->plan != nullptr);
  CHECK(controller->plan->q.size() == 301);
}

// engine/contact/constrained_dynamics.cpp: the M* solve (eq. 32-38): Schur complement ==
// dense LU of M* == the paper's closed form (48)-(49); hand-derived statics of an arm
// leaning on its elbow; dependent rows solved for minimum-norm forces.
#include <doctest/doctest.h>

#include <Eigen/LU>

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/motor.hpp"
#include "engine/run/simulator.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("M* solve: Schur == dense LU of the full M* (eq. 35) == paper's formula (48) (1e-10)") {
  for (int p = 1; p <= 4; ++p) {
    for (int trial = 0; trial < 5; ++trial) {
      CAPTURE(p);
      CAPTURE(trial);
      const int n = 7;
      const Model m = chain_with_elbows(n, p, 500 + 10 * p + trial);
      Data data(m);
      const Eigen::VectorXd q = 2 * Eigen::VectorXd::Random(n), qd = Eigen::VectorXd::Random(n);
      const Eigen::VectorXd i = Eigen::VectorXd::Random(n), tau = m.km.cwiseProduct(i);
      forward_kinematics(m, data, q);
      set_random_contacts(m, data);
      mass_matrix_crba(m, data);
      bias_torques(m, data, qd);
      constraint_rows(m, data, qd);

      solve_constrained(m, data, tau, ConstraintSolver::schur);
      const Eigen::VectorXd qdd = data.qdd, fn = data.contact.fn;
      // The whole (2s + p) M* of eq. (35) with the current block, by dense LU.
      Eigen::MatrixXd Mstar = Eigen::MatrixXd::Zero(2 * n + p, 2 * n + p);
      Mstar.topLeftCorner(n, n) = data.mass_matrix;
      Mstar.block(0, n, n, p) = -data.contact.Jc.transpose();
      Mstar.block(n, 0, p, n) = data.contact.Jc;
      Mstar.bottomRightCorner(n, n) = m.inductance.asDiagonal();
      const Eigen::VectorXd v = 3 * Eigen::VectorXd::Random(n);
      Eigen::VectorXd b(2 * n + p);
      b << tau - data.bias, data.contact.gamma,
          v - m.resistance.cwiseProduct(i) - m.km.cwiseProduct(qd);
      const Eigen::VectorXd x = Mstar.fullPivLu().solve(b);
      const double scale = qdd.cwiseAbs().maxCoeff() + fn.cwiseAbs().maxCoeff();
      CHECK(approx(x.head(n), qdd, 1e-10 * scale));
      CHECK(approx(x.segment(n, p), fn, 1e-10 * scale));
      // The current block is decoupled: di/dt from the motor model.
      CHECK(approx(x.tail(n), (v - m.resistance.cwiseProduct(i) - m.km.cwiseProduct(qd))
                                  .cwiseQuotient(m.inductance), 1e-10, 1e-12));
      for (ConstraintSolver other : {ConstraintSolver::dense_lu, ConstraintSolver::explicit_inverse}) {
        solve_constrained(m, data, tau, other);
        CHECK(approx(data.qdd, qdd, 1e-10 * scale));
        CHECK(approx(data.contact.fn, fn, 1e-10 * scale));
      }
      // The solution satisfies the acceleration constraint of eq. (15).
      CHECK(approx(Eigen::VectorXd(data.contact.Jc * qdd), data.contact.gamma, 1e-9 * scale));
    }
  }
}

TEST_CASE("statics: elbow force of a 2-link arm leaning on the table == hand-derived (1e-9)") {
  const ElbowArm arm;
  for (double share : {0.2, 0.5, 0.9}) {
    const double tau1 = share * arm.G1();
    const Model m = arm.model(tau1, 0.0);
    const RunResult r = simulate(m, {});
    REQUIRE(r.completed);
    const int fn = r.trajectory.column("fn_elbow");
    const double expected = arm.statics_force(tau1);
    CAPTURE(share);
    for (std::size_t row = 0; row < r.trajectory.rows(); ++row)
      CHECK(approx(r.trajectory.at(row, fn), expected, 1e-9 * expected));
    // Nothing moves: the arm is in equilibrium with the table's push.
    CHECK(std::abs(r.trajectory.at(r.trajectory.rows() - 1, r.trajectory.column("qd0"))) < 1e-9);
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

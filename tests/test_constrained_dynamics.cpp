// The M* solve (eq. 32-38): Schur complement == dense LU of M* == the paper's
// closed form (48)-(49); hand-derived statics of an arm leaning on its elbow.
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

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// Random chain with p elbows on random links, random table normals, rows on.
Model chain_with_elbows(int n, int p, std::uint32_t seed) {
  Model m = random_chain(n, seed);
  for (int k = 0; k < p; ++k)
    m.elbows.push_back({"e" + std::to_string(k), 1 + (k * 2) % (n - 1),
                        0.2 * Eigen::Vector3d::Random(), 0.03});
  m.table = {TableBox{}};
  m.effects.contact = true;
  finalize(m);
  return m;
}

void set_random_contacts(const Model& m, Data& data) {
  data.contact.active.clear();
  for (int k = 0; k < int(m.elbows.size()); ++k) {
    data.contact.active.push_back(k);
    data.contact.normal[k] = Eigen::Vector3d::Random().normalized();
    data.contact.surface[k] = Eigen::Vector3d::Random();
  }
}

}  // namespace

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

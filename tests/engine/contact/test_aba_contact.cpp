// engine/contact/aba_contact.cpp: the O(n p) constrained solve (contact.solver: aba)
// gives the Schur path's qdd and f_n to 1e-10 on random chains of 2 .. 60 joints with
// 0 .. 6 rows, sliding friction or none, dependent rows included (minimum-norm f).
#include <doctest/doctest.h>

#include "engine/contact/aba_contact.hpp"
#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/aba.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/models.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// A random chain with p elbows on random links. With `twin` the last elbow is a copy
// of the first (same link, same ball): its row equals the first's, so the rows are
// dependent whatever n is. Sliding friction (law saturated, mu 0.4) makes Jf != Jc.
Model chain(int n, int p, bool twin, bool friction, std::uint32_t seed) {
  Model m = random_chain(n, seed);
  for (int k = 0; k < p; ++k) {
    const int link = n == 1 ? 0 : 1 + (k * 5 + static_cast<int>(seed)) % (n - 1);
    m.elbows.push_back({'e' + std::to_string(k), link, 0.2 * Eigen::Vector3d::Random(), 0.03});
  }
  if (twin && p >= 2) m.elbows.back() = Elbow{"twin", m.elbows[0].link, m.elbows[0].point, 0.03};
  m.table = {TableBox{}};
  m.effects.contact = true;
  m.effects.friction = friction;
  m.contact.friction.law = FrictionLaw::saturated;
  m.contact.friction.mu = 0.4;
  finalize(m);
  return m;
}

struct Solution {
  Eigen::VectorXd qdd, fn;
  bool dependent = false;
};

Solution solve(const Model& m, Data& data, const Eigen::VectorXd& tau, ConstraintSolver s) {
  data.contact.dependent = false;  // each path decides the rank itself
  solve_constrained(m, data, tau, s);
  return {data.qdd, data.contact.fn, data.contact.dependent};
}

}  // namespace

TEST_CASE("aba contact solve == Schur solve (1e-10) on random chains s = 2..60, p = 0..6") {
  int dependent_cases = 0, cases = 0;
  for (int n : {2, 3, 7, 15, 30, 60}) {
    for (int p = 0; p <= 6; ++p) {
      for (int variant = 0; variant < 4; ++variant) {
        const bool twin = variant & 1, friction = variant & 2;
        CAPTURE(n);
        CAPTURE(p);
        CAPTURE(twin);
        CAPTURE(friction);
        const std::uint32_t seed = static_cast<std::uint32_t>(1000 * n + 10 * p + variant);
        const Model m = chain(n, p, twin, friction, seed);
        Data data(m);
        const Eigen::VectorXd q = 2 * Eigen::VectorXd::Random(n), qd = Eigen::VectorXd::Random(n);
        const Eigen::VectorXd tau = 5 * Eigen::VectorXd::Random(n);
        forward_kinematics(m, data, q);
        set_random_contacts(m, data);
        if (twin && p >= 2) {  // the twin rests on the first elbow's plane
          data.contact.normal[p - 1] = data.contact.normal[0];
          data.contact.surface[p - 1] = data.contact.surface[0];
        }
        mass_matrix_crba(m, data);
        bias_torques(m, data, qd);
        articulated_inertias(m, data);
        constraint_rows(m, data, qd);

        const Solution schur = solve(m, data, tau, ConstraintSolver::schur);
        const Solution aba = solve(m, data, tau, ConstraintSolver::aba);
        const double scale =
            schur.qdd.cwiseAbs().maxCoeff() + (p > 0 ? schur.fn.cwiseAbs().maxCoeff() : 0.0);
        CHECK(aba.dependent == schur.dependent);
        CHECK(approx(aba.qdd, schur.qdd, 1e-10 * scale));
        CHECK(approx(aba.fn, schur.fn, 1e-10 * scale));
        // The rows hold: Jc qdd = gamma (on dependent rows, wherever they can).
        if (!aba.dependent)
          CHECK(
              approx(Eigen::VectorXd(data.contact.Jc * aba.qdd), data.contact.gamma, 1e-9 * scale));
        dependent_cases += aba.dependent;
        ++cases;
      }
    }
  }
  // The sweep did meet dependent rows (twins, and more rows than joints at s = 2, 3).
  CHECK(dependent_cases >= 40);
  CHECK(cases == 6 * 7 * 4);
}

TEST_CASE(
    "aba contact terms: A == Jc M^-1 Jf^T and b == Jc qdd_free - gamma, as the Schur path's") {
  const Model m = chain(20, 4, false, true, 77);
  Data data(m);
  const Eigen::VectorXd q = Eigen::VectorXd::Random(20), qd = Eigen::VectorXd::Random(20);
  const Eigen::VectorXd tau = Eigen::VectorXd::Random(20);
  forward_kinematics(m, data, q);
  set_random_contacts(m, data);
  mass_matrix_crba(m, data);
  bias_torques(m, data, qd);
  articulated_inertias(m, data);
  constraint_rows(m, data, qd);
  const Eigen::MatrixXd Minv = data.mass_matrix.inverse();
  const Eigen::MatrixXd A = data.contact.Jc * Minv * data.contact.Jf.transpose();
  const Eigen::VectorXd b = data.contact.Jc * Minv * (tau - data.bias) - data.contact.gamma;
  aba_contact_terms(m, data, tau);
  CHECK(approx(data.contact.A, A, 1e-10 * A.cwiseAbs().maxCoeff()));
  CHECK(approx(Eigen::VectorXd(-data.contact.rhs), b, 1e-10 * b.cwiseAbs().maxCoeff()));
}

TEST_CASE("constraint_solver: auto is schur below kAbaCrossover joints and aba from it on") {
  Model short_chain = chain(kAbaCrossover - 1, 2, false, false, 5);
  Model long_chain = chain(kAbaCrossover, 2, false, false, 6);
  CHECK(short_chain.contact.solver == ConstraintSolver::automatic);
  CHECK(constraint_solver(short_chain) == ConstraintSolver::schur);
  CHECK(constraint_solver(long_chain) == ConstraintSolver::aba);
  short_chain.contact.solver = ConstraintSolver::aba;
  CHECK(constraint_solver(short_chain) == ConstraintSolver::aba);
  long_chain.contact.solver = ConstraintSolver::schur;
  CHECK(constraint_solver(long_chain) == ConstraintSolver::schur);
  // The paper's method asked for: Walker-Orin's M and the Schur complement.
  long_chain.contact.solver = ConstraintSolver::automatic;
  long_chain.options.dynamics = DynamicsMethod::walker_orin;
  CHECK(constraint_solver(long_chain) == ConstraintSolver::schur);
  long_chain.options.dynamics = DynamicsMethod::crba;
  // Joint friction locks joints through M: the aba path is not used with it.
  long_chain.contact.solver = ConstraintSolver::aba;
  long_chain.effects.joint_friction = true;
  CHECK(constraint_solver(long_chain) == ConstraintSolver::schur);
}

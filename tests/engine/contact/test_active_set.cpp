// engine/contact/active_set.cpp: which elbows rest for the coming step (the LCP on the
// touching elbows), select_active_set on its own: landings, releases, Painleve's paradox
// and dependent rows; and Painleve's paradox stopping a whole run.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/active_set.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/detection.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The sliding arm with friction mu = 3 A / B, where A = Jc M^-1 Jc^T and B = Jc M^-1 Jt^T:
// sliding the way friction pushes the elbow down, the Delassus "matrix" A - mu B of the
// resting elbow is negative, Painleve's paradox. Its initial rates slide the elbow along
// the table (qd in the null space of Jc).
Model painleve_scene() {
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
  return m;
}

}  // namespace

TEST_CASE("friction: high mu in a Painleve configuration stops with a clear message") {
  const Model m = painleve_scene();
  const RunResult r = simulate(m, {});
  CHECK_FALSE(r.completed);
  MESSAGE(r.failure);
  CHECK(r.failure.find("Painleve") != std::string::npos);
  CHECK(r.failure.find("t = 0") != std::string::npos);
}

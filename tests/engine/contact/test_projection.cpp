// engine/contact/projection.cpp: drift control by projection, project_onto_constraints
// and the stage stabilise on their own, and drift over 10 s of sliding for each kind
// of stabilisation.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/detection.hpp"
#include "engine/contact/projection.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/simulator.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The elbow arm 0.1 mm into the table, moving (qd = (0.3, -0.2), so also into it),
// detection done there: the state a step can leave before projection.
struct Sunk {
  ElbowArm arm;
  Model m;
  Eigen::Vector2d q, qd{0.3, -0.2};
  Sunk() : m(arm.model(0.5 * arm.G1(), 0.0)) {
    m.effects.stabilization = Stabilization::projection;
    finalize(m);
    q = Eigen::Vector2d(arm.q1 - 1e-4 / (arm.l1 * std::cos(arm.q1)), arm.q2);
  }
  void place_in(Data& data) const {
    place(m, data, q, qd, 0.3);
    detect_contacts(m, data);
    freeze_frames(data);  // the rows' frame, as a step's start would
  }
};

}  // namespace

TEST_CASE("project_onto_constraints: 0.1 mm in the table back onto C = 0 (1e-12 m), Jc qd = 0") {
  const Sunk s;
  Data data(s.m);
  s.place_in(data);
  REQUIRE(approx(data.contact.detected[0].distance, -1e-4, 1e-8));  // second order: 4e-9 m
  data.contact.active = {0};
  const double worst = project_onto_constraints(s.m, data);
  const Eigen::Vector2d q = data.x.head(2), qd = data.x.segment(2, 2);
  MESSAGE("max |C| after projection ", worst, " m");
  // Gauss-Newton converges quadratically from 1e-4 m: rounding of C (~1e-17 m) is left.
  CHECK(worst < 1e-12);
  // Bullet, independently, finds the elbow on the table.
  detect_contacts(s.m, data);
  CHECK(std::abs(data.contact.detected[0].distance) < 1e-12);
  // The rates: no normal speed left (against 0.1 m/s before), rounding only.
  constraint_rows(s.m, data, qd);
  CHECK(std::abs(data.contact.Cd[0]) < 1e-12);
  // Both corrections are the smallest in the kinetic-energy metric: M dq and M dqd are
  // along Jc^T = (j, 0) (the elbow is on link 0), so their second entry vanishes. For dq,
  // M and Jc change along the 1e-4 step: 1e-3 relative; for dqd they are those of the
  // final q: rounding, 1e-12.
  forward_kinematics(s.m, data, q);
  mass_matrix_crba(s.m, data);
  const Eigen::Vector2d M_dq = data.mass_matrix * (q - s.q), M_dqd = data.mass_matrix * (qd - s.qd);
  CHECK(std::abs(M_dq[1]) < 1e-3 * std::abs(M_dq[0]));
  CHECK(std::abs(M_dqd[1]) < 1e-12 * std::abs(M_dqd[0]));
  CHECK(std::abs(q[1] - s.q[1]) > 0);  // the elbow link moved too: a weighted, not a naive, step
}

TEST_CASE("stabilise: projects the resting elbows and adds the stored-energy change it made") {
  const Sunk s;
  Data data(s.m);
  s.place_in(data);
  data.contact.resting[0] = 1;
  data.contact.projection_energy = 0.5;  // what earlier steps added
  EnergyTerms before, after;
  forward_kinematics(s.m, data, s.q);
  stored_energy(s.m, data, s.qd, data.current, before);
  stabilise(s.m, data);
  const Eigen::Vector2d qd = data.x.segment(2, 2);
  CHECK(data.contact.active == std::vector<int>{0});
  CHECK(std::abs(data.contact.detected[0].distance) < 1e-12);  // detected again, after
  forward_kinematics(s.m, data, data.x.head(2));
  stored_energy(s.m, data, qd, data.current, after);
  const double change = after.mechanical() - before.mechanical();
  MESSAGE("projection changed the stored energy by ", change, " J");
  // The same computation in the same order: rounding only (1e-15 J).
  CHECK(approx(data.contact.projection_energy, 0.5 + change, 1e-15));
  // Lifting the arm 0.1 mm takes ~1e-3 J of potential energy; the speed into the
  // table removed ~1e-3 J of kinetic energy: a change that must be accounted for.
  CHECK(std::abs(change) > 1e-5);
}

TEST_CASE("stabilise without resting elbows changes nothing") {
  const Sunk s;
  Data data(s.m);
  s.place_in(data);
  const Eigen::VectorXd x = data.x;
  stabilise(s.m, data);
  CHECK(data.x == x);
  CHECK(data.contact.active.empty());
  CHECK(data.contact.projection_energy == 0);
}

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

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

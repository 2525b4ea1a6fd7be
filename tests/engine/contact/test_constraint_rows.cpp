// engine/contact/constraint_rows.cpp: the rows of M* for resting elbows (eq. 6-9, 15,
// 31) against finite differences of the constraint C(q) = n.(c(q) - s) - r, Baumgarte's
// terms, and sliding friction (directly, and a spinning rod slowing down as mu f_n says).
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/simulator.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"
#include "support/runs.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

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

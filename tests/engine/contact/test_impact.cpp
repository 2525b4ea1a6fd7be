// engine/contact/impact.cpp: the impact law (Newton restitution on the Delassus
// matrix), apply_impact and the impact stage land_touching_elbows on their own.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/contact/detection.hpp"
#include "engine/contact/impact.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/state_layout.hpp"
#include "engine/run/step.hpp"
#include "support/allocations.hpp"
#include "support/approx.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

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

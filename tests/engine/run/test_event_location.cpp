// engine/run/event_location.cpp: redoing a step and locating a crossing in it,
// on a falling pendulum whose angle passes a threshold at a time a fine
// reference run gives.
#include <doctest/doctest.h>

#include <cmath>

#include "engine/run/event_location.hpp"
#include "engine/run/integrator.hpp"
#include "engine/run/step.hpp"
#include "engine/state_layout.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

TEST_CASE("redo_step: the same step again gives the same state and does not count twice") {
  const Model m = pendulum(IntegratorKind::rk4, 1e-3, 0.1);
  Data data(m);
  reset(m, data);
  data.x_start = data.x;
  integrate_step(m, data, 1e-3);
  const Eigen::VectorXd once = data.x;
  const long steps = data.step_count;
  redo_step(m, data, 0.0, 1e-3);
  CHECK(data.x == once);
  CHECK(data.step_count == steps);
  CHECK(data.t == 1e-3);
}

TEST_CASE("locate_crossing: a threshold of the angle inside a step, to the tolerance, in few evaluations") {
  const Model m = pendulum(IntegratorKind::rk4, 1e-2, 1.0);
  const StateLayout s(m);
  Data data(m);
  reset(m, data);
  const double q0 = data.x[s.q()];
  // The step in which joint 0 has moved by 0.01 rad from its start.
  auto moved = [&](const Model&, Data& d) { return 0.01 - std::abs(d.x[s.q()] - q0); };
  double t0 = 0;
  for (;;) {
    t0 = data.t;
    data.x_start = data.x;
    integrate_step(m, data, 1e-2);
    if (moved(m, data) < 0) break;
  }
  int evaluations = 0;
  const double tau = locate_crossing(m, data, t0, 1e-2, 1e-12, [&](const Model& mm, Data& d) {
    ++evaluations;
    return moved(mm, d);
  });
  MESSAGE("crossing at t0 + ", tau, " s after ", evaluations, " evaluations");
  CHECK(moved(m, data) < 0);           // just past the crossing
  CHECK(moved(m, data) > -1e-9);       // by at most speed x tolerance (and the rounding)
  CHECK(evaluations < 20);             // superlinear, not bisection (33 for 1e-2 / 1e-12)
  CHECK(data.t == doctest::Approx(t0 + tau));
}

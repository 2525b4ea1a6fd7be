// engine/step_grid.hpp: the tolerances of "on the step grid", each a share of
// the grid's spacing, and the decisions made with them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "engine/run/simulator.hpp"
#include "engine/step_grid.hpp"
#include "support/scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::step_grid;
using elbowsim::testing::pendulum;

TEST_CASE("step grid: an instant is reached within rounding, a share of the step at any step") {
  for (double step : {1e-6, 1e-4, 1e-2}) {
    CAPTURE(step);
    CHECK(reached(0, step));
    CHECK(reached(0.5e-9 * step, step));      // rounding: reached
    CHECK_FALSE(reached(1e-8 * step, step));  // a step cut short by 1e-8 of it: not yet
    CHECK_FALSE(reached(2e-9 * step, step));
    CHECK(reached(0.5e-3 * step, step, kFixedEnd));  // the end of a fixed-step run
    CHECK_FALSE(reached(2e-3 * step, step, kFixedEnd));
    const double t = 0.3;
    CHECK(not_earlier(t - 0.5e-9 * step, t, step));
    CHECK_FALSE(not_earlier(t - 1e-8 * step, t, step));
    CHECK(not_later(t + 0.5e-9 * step, t, step));
    CHECK_FALSE(not_later(t + 1e-8 * step, t, step));
  }
}

TEST_CASE("step grid: rows are recognised and cut to within kRow of a step") {
  const double step = 1e-4, interval = 10 * step;
  // t a rounding past row 3 counts as row 3 (the next row is 4), a real
  // remainder before it does not.
  CHECK(next_row(3 * interval + 1e-7 * step, interval, step) == 4);
  CHECK(next_row(3 * interval - 1e-7 * step, interval, step) == 4);  // within kRow: on row 3
  CHECK(next_row(3 * interval - 1e-5 * step, interval, step) == 3);  // before row 3
  CHECK(on_row(3 * interval + 1e-7 * step, 3, interval, step));
  // A sample instant 1e-13 s after a row on a 1e-4 s step (1e-9 of it, at the
  // rounding share's edge; commit 7fafad0) is on the row.
  CHECK(on_row(3 * interval + 1e-13, 3, interval, step));
  CHECK_FALSE(on_row(3 * interval + 2e-6 * step, 3, interval, step));
}

TEST_CASE("step grid: a sample period of one step passes, a shorter one does not") {
  CHECK_FALSE(shorter_than_step(1.0 / 1000, 1e-3));
  CHECK_FALSE(shorter_than_step(1e-3 * (1 - 1e-12), 1e-3));  // rounding of 1 / rate
  CHECK(shorter_than_step(1e-3 * (1 - 1e-8), 1e-3));
}

TEST_CASE("step grid: whole spacings count a span a rounding short of a whole number") {
  CHECK(whole_spacings(2.0 * 30) == 60);
  CHECK(whole_spacings(30 * (1 - 1e-15)) == 30);  // 1 s at 30 frames/s, a rounding short
  CHECK(whole_spacings(30 * (1 - 1e-8)) == 29);   // really short of the 30th frame
  CHECK(whole_spacings(0.0) == 0);
}

TEST_CASE("step grid: recorded times are the same instant within 1e-9 of max(1 s, t)") {
  // trajectory.csv prints times to 12 significant digits.
  char text[32];
  for (double t : {0.0123456789012345, 1.23456789012345, 12345.6789012345}) {
    CAPTURE(t);
    std::snprintf(text, sizeof text, "%.12g", t);
    CHECK(same_recorded_time(std::strtod(text, nullptr), t));
    CHECK_FALSE(same_recorded_time(t + 1e-4 * std::max(1.0, t), t));  // a row later
  }
  CHECK(recorded_time_tolerance(0.5) == 1e-9);
  CHECK(recorded_time_tolerance(-2000) == doctest::Approx(2e-6).epsilon(1e-12));
}

TEST_CASE("step grid: a fixed-step run ends within a thousandth of a step, not a step later") {
  // 0.1 s in steps of 1e-3 s: t reaches 0.1 only up to rounding. The run takes
  // 100 steps and records its 101 rows, none of them a sliver after the end.
  const Model m = pendulum(IntegratorKind::rk4, 1e-3, 0.1);
  const RunResult r = simulate(m, RunOptions{1, {}});
  CHECK(r.completed);
  CHECK(r.steps == 100);
  CHECK(r.trajectory.rows() == 101);
  // A duration 1e-4 of a step past a whole number of steps: the remainder is
  // below kFixedEnd, so no step is taken for it.
  Model longer = m;
  longer.options.duration = 0.1 + 1e-7;
  const RunResult l = simulate(longer, RunOptions{1, {}});
  CHECK(l.completed);
  CHECK(l.steps == 100);
}

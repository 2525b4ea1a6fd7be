// engine/control/task.cpp: the quintic time scaling and the desired hand point of each
// path (hold, line, circle, waypoints) at chosen times.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "engine/control/task.hpp"
#include "support/approx.hpp"

using namespace elbowsim;
using elbowsim::testing::approx;

TEST_CASE("time scaling: s(0) = 0, s(1) = 1, s' and s'' zero at both ends, clamped outside") {
  for (HandTask::Timing timing : {HandTask::Timing::quintic, HandTask::Timing::minimum_jerk}) {
    CHECK(time_scaling(timing, 0.0) == Eigen::Vector3d::Zero());
    CHECK(time_scaling(timing, 1.0) == Eigen::Vector3d(1, 0, 0));
    CHECK(time_scaling(timing, -0.5) == Eigen::Vector3d::Zero());
    CHECK(time_scaling(timing, 1.5) == Eigen::Vector3d(1, 0, 0));
    // The polynomial itself meets the clamped values: near the ends s - s_end = O(e^3),
    // s' = O(e^2) (30 e^2), s'' = O(e) (60 e), here with e = 1e-6.
    const double e = 1e-6;
    const Eigen::Vector3d start = time_scaling(timing, e), end = time_scaling(timing, 1 - e);
    CHECK(std::abs(start[0]) <= 11 * e * e * e);
    CHECK(std::abs(start[1]) <= 31 * e * e);
    CHECK(std::abs(start[2]) <= 61 * e);
    CHECK(std::abs(end[0] - 1) <= 11 * e * e * e + 2e-15);  // + rounding of terms of order 10
    CHECK(std::abs(end[1]) <= 31 * e * e);
    CHECK(std::abs(end[2]) <= 61 * e);
    // Symmetric about the middle, with the peak rate 15/8 there.
    CHECK(time_scaling(timing, 0.5) == Eigen::Vector3d(0.5, 1.875, 0.0));
  }
  // Minimum jerk rest-to-rest is the same quintic (Flash & Hogan).
  for (double tau : {0.1, 0.37, 0.8})
    CHECK(time_scaling(HandTask::Timing::minimum_jerk, tau) == time_scaling(HandTask::Timing::quintic, tau));
}

TEST_CASE("time scaling: s' and s'' are the derivatives of s (central differences, 1e-7)") {
  const double h = 1e-5;  // truncation ~h^2 * 100, roundoff ~1e-16 / h^2 for s''
  for (double tau : {0.05, 0.3, 0.5, 0.77, 0.95}) {
    CAPTURE(tau);
    const Eigen::Vector3d s = time_scaling(HandTask::Timing::quintic, tau);
    const Eigen::Vector3d up = time_scaling(HandTask::Timing::quintic, tau + h);
    const Eigen::Vector3d down = time_scaling(HandTask::Timing::quintic, tau - h);
    CHECK(approx(s[1], (up[0] - down[0]) / (2 * h), 1e-7));
    CHECK(approx(s[2], (up[1] - down[1]) / (2 * h), 1e-7));
  }
}

TEST_CASE("hand_target of a line: start, middle and end, with rates from the time scaling") {
  HandTask task;
  task.path = HandTask::Path::line;
  task.points = {Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(0.5, 0.2, 0.1)};
  task.start_delay = 0.5;
  task.duration = 2.0;
  const Eigen::Vector3d start(9, 9, 9);  // used only for an empty first point
  const Eigen::Vector3d d = task.points[1] - task.points[0];
  for (double t : {0.0, 0.5}) {  // holding before and at the start
    const HandTarget h = hand_target(task, start, t);
    CHECK(h.p == task.points[0]);
    CHECK(h.v == Eigen::Vector3d::Zero());
  }
  const HandTarget mid = hand_target(task, start, 1.5);  // tau = 1/2
  CHECK(approx(mid.p, Eigen::Vector3d(0.3, 0.2, 0.2), 1e-15));
  CHECK(approx(mid.v, Eigen::Vector3d(d * 1.875 / 2.0), 1e-15));  // s'(1/2) / duration
  CHECK(approx(mid.a, Eigen::Vector3d::Zero(), 1e-15));           // s''(1/2) = 0
  const HandTarget end = hand_target(task, start, 2.5);
  CHECK(approx(end.p, task.points[1], 1e-15));
  CHECK(end.v == Eigen::Vector3d::Zero());
  CHECK(hand_target(task, start, 7.0).p == end.p);  // holds the end
}

TEST_CASE("hand_target of a circle in the x-z plane: a full turn from +x, rates at the middle") {
  // Normal +y: e1 = +x, e2 = n x e1 = -z. Half way (s = 1/2) the point is opposite the start,
  // moving along -e2 = +z at r 2 pi s'(1/2) / T, accelerating toward the centre at
  // r (2 pi s'(1/2) / T)^2 (s''(1/2) = 0). Rounding of pi: 1e-14.
  HandTask task;
  task.path = HandTask::Path::circle;
  task.center = Eigen::Vector3d(0.4, 0.0, 0.2);
  task.radius = 0.05;
  task.normal = Eigen::Vector3d::UnitY();
  task.duration = 1.5;
  const double r = 0.05, T = 1.5, w = 2 * std::numbers::pi * 1.875 / T;
  const Eigen::Vector3d none(9, 9, 9);
  CHECK(approx(hand_target(task, none, 0.0).p, Eigen::Vector3d(0.45, 0.0, 0.2), 1e-15));
  const HandTarget mid = hand_target(task, none, 0.75);
  CHECK(approx(mid.p, Eigen::Vector3d(0.35, 0.0, 0.2), 1e-14));
  CHECK(approx(mid.v, Eigen::Vector3d(0, 0, r * w), 1e-14));
  CHECK(approx(mid.a, Eigen::Vector3d(r * w * w, 0, 0), 1e-12));
  CHECK(approx(hand_target(task, none, 1.5).p, Eigen::Vector3d(0.45, 0.0, 0.2), 1e-14));  // closed
}

TEST_CASE("hand_target: velocity and acceleration are the time derivatives of the position") {
  HandTask line, circle, waypoints;
  line.path = HandTask::Path::line;
  line.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.2, -0.1, 0.05)};
  circle.path = HandTask::Path::circle;
  circle.normal = Eigen::Vector3d(0.2, 1.0, 0.3);
  circle.start_angle = 0.4;
  waypoints.path = HandTask::Path::waypoints;
  waypoints.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0, 0.05),
                      Eigen::Vector3d(0.2, 0.05, 0.0), Eigen::Vector3d(0.25, 0.1, 0.1)};
  const double h = 1e-5;  // central differences: truncation ~h^2, roundoff ~1e-16 / h
  for (HandTask* task : {&line, &circle, &waypoints}) {
    task->duration = 1.2;
    task->start_delay = 0.1;
    for (double t : {0.2, 0.55, 0.9, 1.25}) {
      CAPTURE(int(task->path));
      CAPTURE(t);
      const Eigen::Vector3d none = Eigen::Vector3d::Zero();
      const HandTarget now = hand_target(*task, none, t), up = hand_target(*task, none, t + h),
                       down = hand_target(*task, none, t - h);
      CHECK(approx(now.v, Eigen::Vector3d((up.p - down.p) / (2 * h)), 1e-8));
      CHECK(approx(now.a, Eigen::Vector3d((up.v - down.v) / (2 * h)), 1e-7));
    }
  }
  // Waypoints end at the last point when the time scaling does (s = 1).
  CHECK(approx(hand_target(waypoints, Eigen::Vector3d::Zero(), 1.3).p, waypoints.points[3], 1e-15));
}

TEST_CASE("hand_target: no points, or a NaN first point, means the hand's start") {
  HandTask hold;
  hold.path = HandTask::Path::hold;
  const Eigen::Vector3d start(0.3, -0.1, 0.2);
  CHECK(hand_target(hold, start, 0.7).p == start);
  HandTask line;
  line.path = HandTask::Path::line;
  line.points = {Eigen::Vector3d::Constant(NAN), Eigen::Vector3d(0.5, -0.1, 0.2)};
  CHECK(hand_target(line, start, 0.0).p == start);
  CHECK(approx(hand_target(line, start, 0.5).p, Eigen::Vector3d(0.4, -0.1, 0.2), 1e-15));
}

TEST_CASE("hand_target of a circle: every point on the circle of radius r in the plane normal to n") {
  // |p - c| = r and (p - c).n = 0 at every time, for any plane normal. Rounding: 1e-15 m.
  for (const Eigen::Vector3d& normal :
       {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0),
        Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 1, 0.3)}) {
    HandTask task;
    task.path = HandTask::Path::circle;
    task.center = Eigen::Vector3d(0.4, 0.1, 0.2);
    task.radius = 0.05;
    task.normal = normal;
    task.start_angle = 0.3;
    const Eigen::Vector3d n = normal.normalized();
    double worst_radius = 0, worst_plane = 0;
    for (double t = 0; t <= 1.0; t += 0.05) {
      const Eigen::Vector3d p = hand_target(task, Eigen::Vector3d::Zero(), t).p - task.center;
      worst_radius = std::max(worst_radius, std::abs(p.norm() - task.radius));
      worst_plane = std::max(worst_plane, std::abs(p.dot(n)));
    }
    CAPTURE(normal.transpose());
    CHECK(worst_radius < 1e-15);
    CHECK(worst_plane < 1e-15);
  }
}

TEST_CASE("hand_target of a circle whose normal is near +y but tilted: still on the circle") {
  HandTask task;
  task.path = HandTask::Path::circle;
  task.center = Eigen::Vector3d(0.4, 0.1, 0.2);
  task.radius = 0.05;
  task.normal = Eigen::Vector3d(0.2, 1.0, 0.3);
  const Eigen::Vector3d n = task.normal.normalized();
  double worst_radius = 0, worst_plane = 0;
  for (double t = 0; t <= 1.0; t += 0.05) {
    const Eigen::Vector3d p = hand_target(task, Eigen::Vector3d::Zero(), t).p - task.center;
    worst_radius = std::max(worst_radius, std::abs(p.norm() - task.radius));
    worst_plane = std::max(worst_plane, std::abs(p.dot(n)));
  }
  MESSAGE("normal (0.2, 1, 0.3): radius off by ", worst_radius, " m, out of plane by ", worst_plane, " m");
  CHECK(worst_radius < 1e-15);
  CHECK(worst_plane < 1e-15);
}

TEST_CASE("hand_target with from_start: points and centre are offsets from the start, exactly") {
  // The same line and circle given as world positions and as offsets from
  // the start must give the same targets (the offset is added once; the sums
  // below are exact in binary only up to rounding of one addition: 1e-16).
  const Eigen::Vector3d start(0.62, 0.0, -0.0325);
  HandTask world, offset;
  world.path = offset.path = HandTask::Path::line;
  world.duration = offset.duration = 2.0;
  world.points = {Eigen::Vector3d::Constant(NAN), start + Eigen::Vector3d(0.08, 0, 0.01)};
  offset.points = {Eigen::Vector3d::Constant(NAN), Eigen::Vector3d(0.08, 0, 0.01)};
  offset.from_start = true;
  for (double t : {0.0, 0.7, 1.0, 2.0, 3.0}) {
    const HandTarget a = hand_target(world, start, t), b = hand_target(offset, start, t);
    CHECK(approx(a.p, b.p, 1e-16));
    CHECK(approx(a.v, b.v, 1e-15));
  }
  CHECK(hand_target(offset, start, 0.0).p == start);  // `start` stays the start
  HandTask circle_world = world, circle_offset = offset;
  circle_world.path = circle_offset.path = HandTask::Path::circle;
  circle_world.points.clear();
  circle_offset.points.clear();
  circle_world.center = start + Eigen::Vector3d(0, 0, 0.015);
  circle_offset.center = Eigen::Vector3d(0, 0, 0.015);
  circle_world.radius = circle_offset.radius = 0.015;
  circle_world.start_angle = circle_offset.start_angle = std::numbers::pi / 2;  // from the bottom
  for (double t : {0.0, 0.5, 1.3}) {
    CHECK(approx(hand_target(circle_world, start, t).p, hand_target(circle_offset, start, t).p, 1e-16));
  }
  CHECK(approx(hand_target(circle_offset, start, 0.0).p, start, 1e-16));  // starts at the hand
  // Without from_start the offsets are world positions: the hand would jump.
  offset.from_start = false;
  CHECK((hand_target(offset, start, 2.0).p - hand_target(world, start, 2.0).p).norm() > 0.5);
}

namespace {

// The time at which the quintic time scaling reaches s (bisection; s is
// monotone on [0, 1]), for a task without delay and duration 1.
double time_at(double s) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (time_scaling(HandTask::Timing::quintic, mid)[0] < s ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

//   P1 o       o P3
//     / \     / \        waypoints through a natural cubic spline on
//  P0o   \   /   o P4    chord-length knots: through every point, C2, and
//         o P2           straight (zero curvature) at both ends
TEST_CASE("hand_target of waypoints: a C2 natural spline through every point at its chord-length parameter") {
  HandTask task;
  task.path = HandTask::Path::waypoints;
  task.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.02, 0, 0.03),
                 Eigen::Vector3d(0.05, 0.01, -0.01), Eigen::Vector3d(0.06, 0, 0.02),
                 Eigen::Vector3d(0.1, 0, 0)};
  const Eigen::Vector3d none = Eigen::Vector3d::Zero();
  std::vector<double> knot{0};
  for (std::size_t i = 1; i < task.points.size(); ++i)
    knot.push_back(knot.back() + (task.points[i] - task.points[i - 1]).norm());
  for (std::size_t i = 0; i < task.points.size(); ++i) {
    CAPTURE(i);
    // Through the point: bisection puts t within 1e-16 s, the hand within 1e-15 m.
    const double t = time_at(knot[i] / knot.back());
    CHECK(approx(hand_target(task, none, t).p, task.points[i], 1e-12));
    if (i == 0 || i + 1 == task.points.size()) continue;
    // C2 at an interior point: the acceleration 1e-6 s before and after differs
    // by about jerk x 2e-6 s (jerk here below 1e3 m/s^3: < 2e-3 m/s^2); a C1
    // spline's jump at a point is of the order of the acceleration (~1 m/s^2).
    const Eigen::Vector3d before = hand_target(task, none, t - 1e-6).a;
    const Eigen::Vector3d after = hand_target(task, none, t + 1e-6).a;
    CHECK((after - before).norm() < 2e-3);
    CHECK(after.norm() > 0.1);  // (the acceleration there is not zero by itself)
  }
  // Natural ends: d2p/du2 = 0 at u = 0. With s'(0) = s''(0) = 0 the hand's
  // acceleration vanishes there anyway; check the curve by a path whose time
  // scaling is past its start: the line from P0 to the next point is tangent
  // and straight, so p(s) - P0 is parallel to dp/ds to second order.
  const double t = time_at(1e-4);
  const HandTarget near = hand_target(task, none, t);
  const Eigen::Vector3d chord = near.p - task.points[0];
  CHECK(chord.normalized().cross(near.v.normalized()).norm() < 1e-6);
}

TEST_CASE("hand_target of waypoints: a point repeated is dropped, not a division by zero") {
  HandTask task, repeated;
  task.path = repeated.path = HandTask::Path::waypoints;
  task.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0, 0.05), Eigen::Vector3d(0.2, 0, 0)};
  repeated.points = {task.points[0], task.points[1], task.points[1], task.points[2]};
  for (double t : {0.0, 0.3, 0.5, 0.8, 1.0}) {
    const HandTarget a = hand_target(task, Eigen::Vector3d::Zero(), t);
    const HandTarget b = hand_target(repeated, Eigen::Vector3d::Zero(), t);
    CHECK(b.p.allFinite());
    CHECK(approx(a.p, b.p, 1e-15));
    CHECK(approx(a.a, b.a, 1e-12));
  }
}

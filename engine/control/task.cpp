#include "engine/control/task.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace elbowsim {

// The minimum-jerk rest-to-rest profile is the quintic 10t^3 - 15t^4 + 6t^5
// (Flash & Hogan 1985), so both names give it; they differ only for paths
// that would need via-point optimisation, which we do not do.
Eigen::Vector3d time_scaling(HandTask::Timing, double tau) {
  if (tau <= 0) return Eigen::Vector3d::Zero();
  if (tau >= 1) return Eigen::Vector3d(1, 0, 0);
  const double t2 = tau * tau, t3 = t2 * tau;
  return {t3 * (10 - 15 * tau + 6 * t2), 30 * t2 * (1 - 2 * tau + t2), 60 * tau * (1 - 3 * tau + 2 * t2)};
}

namespace {

struct Curve {  // position and first two derivatives with respect to the path parameter
  Eigen::Vector3d p, dp, ddp;
};

// Catmull-Rom spline through the points, parameter u in [0, n-1].
Curve waypoints(const std::vector<Eigen::Vector3d>& pts, double u) {
  const int n = int(pts.size());
  const int k = std::clamp(int(std::floor(u)), 0, n - 2);
  const double s = u - k;
  auto at = [&](int i) { return pts[std::clamp(i, 0, n - 1)]; };
  const Eigen::Vector3d p0 = at(k - 1), p1 = at(k), p2 = at(k + 1), p3 = at(k + 2);
  const Eigen::Vector3d a = 2 * p1, b = p2 - p0, c = 2 * p0 - 5 * p1 + 4 * p2 - p3,
                        d = -p0 + 3 * p1 - 3 * p2 + p3;
  return {0.5 * (a + b * s + c * s * s + d * s * s * s), 0.5 * (b + 2 * c * s + 3 * d * s * s),
          0.5 * (2 * c + 6 * d * s)};
}

Curve circle(const HandTask& task, const Eigen::Vector3d& center, double s) {
  const Eigen::Vector3d n = task.normal.normalized();
  // Start along +x projected into the circle's plane (for a planar arm's x-z
  // plane exactly +x); a normal along x starts along any perpendicular.
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX() - n.x() * n;
  e1 = e1.norm() > 1e-6 ? e1.normalized() : n.unitOrthogonal();
  const Eigen::Vector3d e2 = n.cross(e1);
  const double w = 2 * std::numbers::pi, th = task.start_angle + w * s;
  const Eigen::Vector3d radial = std::cos(th) * e1 + std::sin(th) * e2;
  const Eigen::Vector3d tangent = -std::sin(th) * e1 + std::cos(th) * e2;
  return {center + task.radius * radial, task.radius * w * tangent,
          -task.radius * w * w * radial};
}

Curve curve(const HandTask& task, const std::vector<Eigen::Vector3d>& pts,
            const Eigen::Vector3d& center, double s) {
  switch (task.path) {
    case HandTask::Path::none:
    case HandTask::Path::hold: return {pts[0], Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    case HandTask::Path::line: return {pts[0] + s * (pts[1] - pts[0]), pts[1] - pts[0], Eigen::Vector3d::Zero()};
    case HandTask::Path::circle: return circle(task, center, s);
    case HandTask::Path::waypoints: {
      const double span = double(pts.size() - 1);
      Curve c = waypoints(pts, s * span);
      c.dp *= span;
      c.ddp *= span * span;
      return c;
    }
  }
  return {pts[0], Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
}

}  // namespace

HandTarget hand_target(const HandTask& task, const Eigen::Vector3d& start, double t) {
  std::vector<Eigen::Vector3d> pts = task.points;
  const Eigen::Vector3d origin = task.from_start ? start : Eigen::Vector3d::Zero();
  for (Eigen::Vector3d& p : pts) p += origin;
  if (pts.empty()) pts.push_back(start);
  if (!pts[0].allFinite()) pts[0] = start;
  const Eigen::Vector3d s = time_scaling(task.timing, (t - task.start_delay) / task.duration);
  const double sd = s[1] / task.duration, sdd = s[2] / (task.duration * task.duration);
  const Curve c = curve(task, pts, task.center + origin, s[0]);
  return {c.p, c.dp * sd, c.ddp * sd * sd + c.dp * sdd};
}

}  // namespace elbowsim

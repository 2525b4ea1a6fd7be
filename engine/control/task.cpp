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

// The natural cubic spline through the points (Ahlberg, Nilson & Walsh 1967),
// on chord-length knots u_0 = 0, u_i = u_(i-1) + |P_i - P_(i-1)|: C2 in u, so
// with a C2 time scaling the hand's planned acceleration has no jumps (a
// Catmull-Rom spline is only C1: its acceleration jumps at every point). The
// second derivatives M_i at the knots solve the tridiagonal system
//   h_(i-1) M_(i-1) + 2 (h_(i-1) + h_i) M_i + h_i M_(i+1)
//     = 6 ((P_(i+1) - P_i) / h_i - (P_i - P_(i-1)) / h_(i-1)),   M_0 = M_(n-1) = 0,
// by the Thomas algorithm (diagonally dominant: no pivoting). A point equal
// to the one before it (within 1e-12 m) adds no chord and is dropped.
// Parameter s in [0, 1] maps to u = s u_(n-1); derivatives are with respect to s.
Curve waypoints(std::vector<Eigen::Vector3d> pts, double s) {
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
                          return (a - b).norm() <= 1e-12;
                        }),
            pts.end());
  const int n = int(pts.size());
  if (n < 2) return {pts[0], Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::vector<double> h(std::size_t(n - 1)), knot(std::size_t(n), 0.0);
  for (int i = 0; i + 1 < n; ++i) {
    h[std::size_t(i)] = (pts[std::size_t(i + 1)] - pts[std::size_t(i)]).norm();
    knot[std::size_t(i + 1)] = knot[std::size_t(i)] + h[std::size_t(i)];
  }
  // Forward sweep of the Thomas algorithm on rows 1 .. n-2, then back substitution.
  std::vector<Eigen::Vector3d> M(std::size_t(n), Eigen::Vector3d::Zero()), rhs(M);
  std::vector<double> upper(std::size_t(n), 0.0);
  for (int i = 1; i + 1 < n; ++i) {
    const double hl = h[std::size_t(i - 1)], hr = h[std::size_t(i)];
    const Eigen::Vector3d r = 6 * ((pts[std::size_t(i + 1)] - pts[std::size_t(i)]) / hr -
                                   (pts[std::size_t(i)] - pts[std::size_t(i - 1)]) / hl);
    const double pivot = 2 * (hl + hr) - hl * upper[std::size_t(i - 1)];
    upper[std::size_t(i)] = hr / pivot;
    rhs[std::size_t(i)] = (r - hl * rhs[std::size_t(i - 1)]) / pivot;
  }
  for (int i = n - 2; i >= 1; --i)
    M[std::size_t(i)] = rhs[std::size_t(i)] - upper[std::size_t(i)] * M[std::size_t(i + 1)];
  // The segment holding u, and the spline there.
  const double total = knot.back(), u = std::clamp(s, 0.0, 1.0) * total;
  int k = 0;
  while (k < n - 2 && u > knot[std::size_t(k + 1)]) ++k;
  const double hk = h[std::size_t(k)], b = u - knot[std::size_t(k)], a = hk - b;
  const Eigen::Vector3d &P0 = pts[std::size_t(k)], &P1 = pts[std::size_t(k + 1)];
  const Eigen::Vector3d &M0 = M[std::size_t(k)], &M1 = M[std::size_t(k + 1)];
  const Eigen::Vector3d c0 = P0 / hk - M0 * hk / 6, c1 = P1 / hk - M1 * hk / 6;
  const Eigen::Vector3d p = (M0 * a * a * a + M1 * b * b * b) / (6 * hk) + c0 * a + c1 * b;
  const Eigen::Vector3d dp = (M1 * b * b - M0 * a * a) / (2 * hk) - c0 + c1;
  const Eigen::Vector3d ddp = (M0 * a + M1 * b) / hk;
  return {p, dp * total, ddp * total * total};
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
    case HandTask::Path::waypoints: return waypoints(pts, s);
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

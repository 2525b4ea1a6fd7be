#include "engine/contact/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace elbowsim {

const char* to_string(BoxFeature f) {
  switch (f) {
    case BoxFeature::face: return "face";
    case BoxFeature::edge: return "edge";
    case BoxFeature::corner: return "corner";
    case BoxFeature::inside: return "inside";
  }
  return "?";
}

BoxContact sphere_box(const Eigen::Vector3d& centre, double radius, const TableBox& box) {
  const Eigen::Vector3d h = 0.5 * box.size;
  const Eigen::Vector3d x = box.rotation.transpose() * (centre - box.center);  // box frame
  const Eigen::Vector3d q = x.cwiseMax(-h).cwiseMin(h);  // nearest point of the solid box
  int clamped = 0, axis = -1;
  for (int i = 0; i < 3; ++i)
    if (x[i] != q[i]) ++clamped, axis = i;
  BoxContact c;
  Eigen::Vector3d surface = q, normal = Eigen::Vector3d::Zero();
  if (clamped == 0) {
    // Inside: the face with the least penetration.
    int best = 0;
    for (int i = 1; i < 3; ++i)
      if (h[i] - std::abs(x[i]) < h[best] - std::abs(x[best])) best = i;
    const double side = x[best] >= 0 ? 1.0 : -1.0;
    surface[best] = side * h[best];
    normal[best] = side;
    c.distance = -(h[best] - std::abs(x[best])) - radius;
    c.feature = BoxFeature::inside;
    c.face_axis = best;
  } else if (clamped == 1) {
    // Over a face: the face axis itself, the distance along it.
    const double side = x[axis] > 0 ? 1.0 : -1.0;
    normal[axis] = side;
    c.distance = side * x[axis] - h[axis] - radius;
    c.feature = BoxFeature::face;
    c.face_axis = axis;
  } else {
    // Beside an edge or a corner: from the nearest point to the centre.
    const Eigen::Vector3d d = x - q;
    const double length = d.norm();
    normal = d / length;
    c.distance = length - radius;
    c.feature = clamped == 2 ? BoxFeature::edge : BoxFeature::corner;
    if (clamped == 2)
      for (int i = 0; i < 3; ++i)
        if (x[i] == q[i]) c.edge = box.rotation.col(i);
  }
  c.normal = box.rotation * normal;
  c.point = box.center + box.rotation * surface;
  return c;
}

namespace {

// How far outside the box's slab i the coordinate v lies (0 inside): (|v| - h)+.
double outside(double v, double h) { return std::max(std::abs(v) - h, 0.0); }

double squared_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& h) {
  double f = 0;
  for (int i = 0; i < 3; ++i) f += outside(x[i], h[i]) * outside(x[i], h[i]);
  return f;
}

// Depth inside the box (min over faces of h_i - |x_i|), negative outside.
double depth(const Eigen::Vector3d& x, const Eigen::Vector3d& h) {
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) d = std::min(d, h[i] - std::abs(x[i]));
  return d;
}

}  // namespace

double segment_box_parameter(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const TableBox& box) {
  const Eigen::Vector3d h = 0.5 * box.size;
  const Eigen::Vector3d xa = box.rotation.transpose() * (a - box.center);
  const Eigen::Vector3d dx = box.rotation.transpose() * (b - a);
  auto at = [&](double t) -> Eigen::Vector3d { return xa + t * dx; };
  // Where a coordinate crosses a slab face: the pieces of f(t) = |x(t) - box|^2.
  double cuts[8];
  int n = 0;
  cuts[n++] = 0.0;
  cuts[n++] = 1.0;
  for (int i = 0; i < 3; ++i) {
    if (dx[i] == 0) continue;
    for (double side : {-1.0, 1.0}) {
      const double t = (side * h[i] - xa[i]) / dx[i];
      if (t > 0 && t < 1) cuts[n++] = t;
    }
  }
  // At most 8 cuts: insertion sort. (std::sort's branch for more than 16 values, never
  // taken here, made GCC 12 warn of an access past the array: -Warray-bounds.)
  for (int k = 1; k < n; ++k)
    for (int j = k; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
  // On each piece the clamped axes are fixed, f is quadratic: its minimiser, clamped.
  double best_t = 0, best_f = squared_distance(xa, h);
  for (int k = 0; k + 1 < n; ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    const Eigen::Vector3d mid = at(0.5 * (lo + hi));
    double num = 0, den = 0;
    for (int i = 0; i < 3; ++i) {
      if (std::abs(mid[i]) <= h[i]) continue;
      const double target = mid[i] > 0 ? h[i] : -h[i];
      num -= dx[i] * (xa[i] - target);
      den += dx[i] * dx[i];
    }
    for (double t : {lo, hi, den > 0 ? std::clamp(num / den, lo, hi) : lo}) {
      const double f = squared_distance(at(t), h);
      if (f < best_f) best_f = f, best_t = t;
    }
  }
  // Outside by more than rounding: the nearest point. (A minimiser that only
  // grazes the surface by rounding still looks for a deeper point.)
  const double grazing = 1e-12 * (1.0 + h.norm());
  if (best_f > grazing * grazing) return best_t;
  // The segment enters the box: the deepest point. The depth is concave and
  // piecewise linear in t, so its maximum is at an end, a slab crossing or
  // where two of its linear pieces h_i -+ x_i(t) meet (x_i = 0 for one axis).
  double best_depth = depth(at(best_t), h);
  auto consider = [&](double t) {
    if (!(t >= 0 && t <= 1)) return;
    const double d = depth(at(t), h);
    if (d > best_depth) best_depth = d, best_t = t;
  };
  for (int k = 0; k < n; ++k) consider(cuts[k]);
  for (int i = 0; i < 3; ++i)
    if (dx[i] != 0) consider(-xa[i] / dx[i]);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      for (double si : {-1.0, 1.0})
        for (double sj : {-1.0, 1.0}) {
          // h_i - si x_i(t) = h_j - sj x_j(t)
          const double slope = si * dx[i] - sj * dx[j];
          if (slope != 0) consider((h[i] - h[j] - si * xa[i] + sj * xa[j]) / slope);
        }
  return best_t;
}

Eigen::AlignedBox3d box_bounds(const TableBox& box) {
  const Eigen::Vector3d half = 0.5 * (box.rotation.cwiseAbs() * box.size);
  return Eigen::AlignedBox3d(box.center - half, box.center + half);
}

}  // namespace elbowsim

#include "render/instances.hpp"

#include <algorithm>
#include <cmath>

namespace elbowsim {

namespace {

constexpr double kDashRadius = 0.04;  // drop-line tube radius / elbow radius

// A unit shape along z from a to b with the given radius.
void add_along(std::vector<float>& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
               double radius, const Color& color) {
  const Eigen::Vector3d d = b - a;
  const double length = d.norm();
  if (length < 1e-9 || radius <= 0) return;
  const Eigen::Matrix3d linear =
      frame_with_z(d / length) * Eigen::Vector3d(radius, radius, length).asDiagonal();
  add_instance(out, linear, a, color);
}

void add_sphere(std::vector<float>& out, const Eigen::Vector3d& c, double r, const Color& color) {
  if (r > 0) add_instance(out, r * Eigen::Matrix3d::Identity(), c, color);
}

// Half a sphere of radius r about c, bulging toward `outward`.
void add_dome(ShapeInstances& out, const Eigen::Vector3d& c, const Eigen::Vector3d& outward,
              double r, const Color& color) {
  if (outward.norm() < 1e-9) return add_sphere(out[sphere], c, r, color);
  if (r > 0) add_instance(out[dome], r * frame_with_z(outward.normalized()), c, color);
}

void add_path(ShapeInstances& out, const Polyline& path) {
  const auto& p = path.points;
  for (std::size_t k = 1; k < p.size(); ++k)
    add_along(out[tube], p[k - 1], p[k], path.radius, path.color);
}

// Each piece's segments as flat ribbons (squares stretched to width 2
// radius, facing `back`, each a radius longer at both ends so that bends
// stay closed): drawn flat, a ribbon looks like a tube at a small part of
// its triangles.
void add_inset_path(ShapeInstances& out, const InsetPath& path, const Eigen::Vector3d& back) {
  const double r = path.radius;
  for (const std::vector<Eigen::Vector3d>& p : path.pieces)
    for (std::size_t k = 1; k < p.size(); ++k) {
      const Eigen::Vector3d d = p[k] - p[k - 1];
      const Eigen::Vector3d across = d.cross(back);
      if (d.norm() < 1e-12 || across.norm() < 1e-12) continue;
      Eigen::Matrix3d linear;
      linear << 2 * r * across.normalized(), r * back, d + 2 * r * d.normalized();
      add_instance(out[square], linear, 0.5 * (p[k - 1] + p[k]), path.color);
    }
}

void add_arm(const Scene& s, ShapeInstances& out) {
  add_instance(out[box], s.base.rotation * s.base.size.asDiagonal(), s.base.center, s.base.color);
  // A capsule as an open shaft and a dome at each end: a capped cylinder and
  // two whole spheres drew twice the triangles, half of them hidden inside.
  for (const Capsule& c : s.links) {
    add_along(out[shaft], c.a, c.b, c.radius, c.color);
    add_dome(out, c.a, c.a - c.b, c.radius, c.color);
    add_dome(out, c.b, c.b - c.a, c.radius, c.color);
  }
  for (const Cylinder& c : s.joints) add_along(out[cylinder], c.a, c.b, c.radius, c.color);
  for (const ElbowMarker& e : s.elbows)
    add_sphere(out[sphere], e.sphere.center, e.sphere.radius, e.sphere.color);
  for (const Arrow& a : s.forces) {
    const double length = (a.tip - a.tail).norm();
    const double head = std::min(0.4 * length, 4.0 * a.radius);
    const Eigen::Vector3d neck = a.tip + (a.tail - a.tip).normalized() * head;
    add_along(out[cylinder], a.tail, neck, a.radius, a.color);
    add_along(out[cone], neck, a.tip, 2.2 * a.radius, a.color);
  }
}

// The table, and per contact cue a ring lying on the table top (its tube
// half sunk, so it reads as a mark on the table) and the drop line's dashes.
void add_ground(const Scene& s, ShapeInstances& out) {
  for (const Box& b : s.table)
    add_instance(out[box], b.rotation * b.size.asDiagonal(), b.center, b.color);
  for (const ContactCue& c : s.cues) {
    add_instance(out[ring], c.radius * frame_with_z(c.normal), c.foot, c.color);
    const double r = kDashRadius * c.radius;
    for (std::size_t k = 1; k < c.dashes.size(); k += 2)
      add_along(out[tube], c.dashes[k - 1], c.dashes[k], r, c.color);
  }
}

// Each unit shape's bounding sphere (meshes.hpp): centre and radius.
struct Bound {
  Eigen::Vector3f centre;
  float radius;
};

Bound unit_bound(int shape) {
  switch (shape) {
    case cylinder:
    case tube:
    case cone:
    case shaft:
      return {{0, 0, 0.5f}, std::sqrt(1.25f)};  // radius 1, z from 0 to 1
    case box:
      return {{0, 0, 0}, std::sqrt(0.75f)};  // [-1/2, 1/2]^3
    case ring:
      return {{0, 0, 0}, float(1 + kRingTube)};
    case square:
      return {{0, 0, 0}, std::sqrt(0.5f)};
    default:
      return {{0, 0, 0}, 1.0f};  // the unit sphere, and the dome (its half)
  }
}

}  // namespace

void cull_to_window(const ShapeInstances& in, const Camera& camera, ShapeInstances& out) {
  const CameraBasis basis = camera.basis();
  const Eigen::Vector3f right = basis.right.cast<float>(), up = basis.up.cast<float>();
  const Eigen::Vector3f target = camera.target.cast<float>();
  const float half_h = float(0.5 * camera.ortho_height), half_w = half_h * float(camera.aspect);
  for (int s = 0; s < shape_count; ++s) {
    const std::vector<float>& from = in[std::size_t(s)];
    std::vector<float>& to = out[std::size_t(s)];
    to.clear();
    const Bound b = unit_bound(s);
    for (std::size_t k = 0; k + kInstanceFloats <= from.size(); k += kInstanceFloats) {
      const Eigen::Map<const Eigen::Matrix4f> model(from.data() + k);
      // The bounding sphere's centre from the window's, and its radius.
      const Eigen::Vector3f d = (model * b.centre.homogeneous()).head<3>() - target;
      const float r = b.radius * model.topLeftCorner<3, 3>().colwise().norm().maxCoeff();
      if (std::abs(d.dot(right)) <= half_w + r && std::abs(d.dot(up)) <= half_h + r)
        to.insert(to.end(), from.begin() + std::ptrdiff_t(k),
                  from.begin() + std::ptrdiff_t(k + kInstanceFloats));
    }
  }
}

void add_instance(std::vector<float>& out, const Eigen::Matrix3d& linear, const Eigen::Vector3d& t,
                  const Color& color) {
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
  model.topLeftCorner<3, 3>() = linear.cast<float>();
  model.topRightCorner<3, 1>() = t.cast<float>();
  const Eigen::Matrix3f normal = linear.inverse().transpose().cast<float>();
  out.insert(out.end(), model.data(), model.data() + 16);
  out.insert(out.end(), normal.data(), normal.data() + 9);
  out.insert(out.end(), {color.r, color.g, color.b, 1.0f});
}

void collect(const Scene& s, Instances& out) {
  for (ShapeInstances& group : out)
    for (std::vector<float>& v : group) v.clear();
  add_arm(s, out[arm]);
  add_ground(s, out[ground]);
  add_path(out[paths], s.hand_path);
  add_path(out[paths], s.desired_hand_path);
}

std::array<ShapeInstances, 3> inset_instances(const Inset& inset) {
  std::array<ShapeInstances, 3> out;
  const Eigen::Vector3d back = (inset.camera.eye - inset.camera.target).normalized();
  add_inset_path(out[0], inset.desired, back);
  add_inset_path(out[1], inset.traced, back);
  add_sphere(out[2][sphere], inset.hand.center, inset.hand.radius, inset.hand.color);
  return out;
}

}  // namespace elbowsim

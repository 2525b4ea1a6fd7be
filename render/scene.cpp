#include "render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/data.hpp"
#include "engine/contact/primitives.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

namespace {

// Proportions of the drawn parts, relative to the link radius r.
constexpr double kHousingRadius = 1.3;  // joint housing radius / r
constexpr double kHousingLength = 2.6;  // joint housing length / r
constexpr double kBasePlate = 5.0;      // base plate edge / r
constexpr double kBaseThickness = 1.0;  // base plate thickness / r
constexpr double kArrowRadius = 0.18;   // arrow shaft radius / elbow radius
constexpr double kPathRadius = 0.002;   // [m] hand path tube radius
constexpr double kDesiredRadius = 0.0012;  // [m] desired hand path tube radius (thinner)
constexpr double kDash = 0.004;            // [m] drop line: one dash and one space, about

Eigen::Vector3d world_up(const Model& model) {
  const double g = model.gravity.norm();
  return g > 0 ? Eigen::Vector3d(-model.gravity / g) : Eigen::Vector3d::UnitZ();
}

// Distance from a point to a (rotated) box; 0 inside.
double distance_to_box(const TableBox& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = box.rotation.transpose() * (p - box.center);
  const Eigen::Vector3d outside = (local.cwiseAbs() - 0.5 * box.size).cwiseMax(0.0);
  return outside.norm();
}

}  // namespace

Eigen::Matrix3d frame_with_z(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d x = helper.cross(n).normalized();
  Eigen::Matrix3d r;
  r << x, n.cross(x), n;
  return r;
}

namespace {

// A plate behind joint 0: its normal along the joint axis, on the side the
// axis points away from (for a planar arm, behind the arm as seen from the front).
Box base_plate(const Model& model, const Data& data, const SceneStyle& style) {
  const double r = model.links.empty() ? 0.02 : model.links[0].radius;
  const Eigen::Vector3d axis = data.axis.empty() ? Eigen::Vector3d::UnitZ() : data.axis[0];
  const Eigen::Vector3d origin = data.origin.empty() ? model.base.translation() : data.origin[0];
  Box plate;
  plate.rotation = frame_with_z(axis);
  plate.size = Eigen::Vector3d(kBasePlate * r, kBasePlate * r, kBaseThickness * r);
  plate.center = origin - axis * (0.5 * kHousingLength * r + 0.5 * plate.size.z());
  plate.color = style.base;
  return plate;
}

// Radius of the largest elbow sphere containing `p`, 0 if none.
double enclosing_elbow(const Model& model, const Data& data, const Eigen::Vector3d& p) {
  double r = 0;
  for (const Elbow& e : model.elbows)
    if ((point_position(data, e.link, e.point) - p).norm() < e.radius) r = std::max(r, e.radius);
  return r;
}

// Links as capsules; a housing at each joint, shrunk to fit inside an elbow
// sphere around the joint so that it does not hide the elbow's colour.
void add_links(const Model& model, const Data& data, Scene& scene, const SceneStyle& style) {
  for (int i = 0; i < model.dof; ++i) {
    const Link& link = model.links[std::size_t(i)];
    scene.links.push_back(
        {data.origin[i], point_position(data, i, link.tip), link.radius, style.link});
    double radius = kHousingRadius * link.radius, half = 0.5 * kHousingLength * link.radius;
    if (const double elbow = enclosing_elbow(model, data, data.origin[i]); elbow > 0) {
      radius = std::min(radius, 0.7 * elbow);
      half = std::min(half, 0.7 * elbow);
    }
    const Eigen::Vector3d h = half * data.axis[i];
    scene.joints.push_back({data.origin[i] - h, data.origin[i] + h, radius, style.joint});
  }
}

ElbowState elbow_state(const ElbowSample& e, double t, double window) {
  if (!e.resting) return t - e.lifted_at <= window ? ElbowState::lifted : ElbowState::free;
  return t - e.landed_at <= window ? ElbowState::landed : ElbowState::resting;
}

Color elbow_color(ElbowState state, const SceneStyle& style) {
  switch (state) {
    case ElbowState::free:
      return style.elbow_free;
    case ElbowState::resting:
      return style.elbow_resting;
    case ElbowState::landed:
      return style.elbow_landed;
    case ElbowState::lifted:
      return style.elbow_lifted;
  }
  return style.elbow_free;
}

// Dashes from a down to b: k dashes and k - 1 equal spaces, each about kDash / 2.
std::vector<Eigen::Vector3d> dashes(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const int k = std::max(2, int(std::lround((b - a).norm() / kDash)));
  const Eigen::Vector3d step = (b - a) / double(2 * k - 1);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < k; ++i) out.insert(out.end(), {a + 2 * i * step, a + (2 * i + 1) * step});
  return out;
}

// The contact cue of an elbow with a recorded distance within cue_range
// radii of the table: the ring at its foot, and the drop line while it is off.
void add_cue(const Model& model, int k, const ElbowSample& sample, ElbowState state,
             const Eigen::Vector3d& centre, Scene& scene, const SceneOptions& options) {
  const double radius = model.elbows[std::size_t(k)].radius;
  if (!sample.distance || *sample.distance > options.cue_range * radius) return;
  const bool on = state == ElbowState::resting || state == ElbowState::landed;
  ContactCue cue;
  cue.elbow = k;
  cue.normal = table_up(model, centre);
  cue.gap = on ? 0.0 : std::max(*sample.distance, 0.0);
  cue.foot = centre - (radius + std::max(*sample.distance, 0.0)) * cue.normal;
  cue.radius = radius;
  cue.color = on || state == ElbowState::lifted ? elbow_color(state, options.style)
                                                : options.style.cue_free;
  if (!on && cue.gap > 0) cue.dashes = dashes(centre - radius * cue.normal, cue.foot);
  scene.cues.push_back(std::move(cue));
}

// Elbow spheres coloured by state, their contact cues, and at each resting
// elbow pushed by the table an arrow from the top of the sphere along the
// table normal, of length fn * force_scale.
void add_elbows(const Model& model, const Data& data, const PlaybackState& state, Scene& scene,
                const SceneOptions& options) {
  for (std::size_t k = 0; k < model.elbows.size(); ++k) {
    const Elbow& elbow = model.elbows[k];
    const ElbowSample sample = k < state.elbows.size() ? state.elbows[k] : ElbowSample{};
    const ElbowState s = elbow_state(sample, state.t, options.landed_window);
    const Eigen::Vector3d centre = point_position(data, elbow.link, elbow.point);
    scene.elbows.push_back({{centre, elbow.radius, elbow_color(s, options.style)}, s});
    add_cue(model, int(k), sample, s, centre, scene, options);
    const double length = sample.fn * options.force_scale;
    if (s == ElbowState::free || s == ElbowState::lifted || length <= 0) continue;
    const Eigen::Vector3d n = table_up(model, centre);
    const Eigen::Vector3d tail = centre + elbow.radius * n;
    scene.forces.push_back({tail, tail + length * n, std::max(kArrowRadius * elbow.radius, 0.002),
                            options.style.force, int(k), -1, sample.fn});
  }
}

// Where link j's own solid rests, seen from above the table (normal n): over
// the lowest of its primitives' ends (balls and segment ends; the middle of
// those within 1 mm of the lowest), on the solid's top, where an elbow's
// arrow starts too.
std::optional<Eigen::Vector3d> link_contact_top(const Data& data, int j, const Eigen::Vector3d& n) {
  struct End {
    Eigen::Vector3d centre;
    double radius;
  };
  std::vector<End> ends;
  double lowest = INFINITY;
  for (const Primitive& p : data.contact.geometry.primitives) {
    if (p.elbow >= 0 || p.link != j) continue;
    for (const Eigen::Vector3d& local : {p.a, p.b}) {
      ends.push_back({point_position(data, j, local), p.radius});
      lowest = std::min(lowest, n.dot(ends.back().centre) - p.radius);
    }
  }
  if (ends.empty()) return std::nullopt;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (const End& e : ends)
    if (n.dot(e.centre) - e.radius <= lowest + 1e-3) sum += e.centre + e.radius * n, ++count;
  return sum / count;
}

// At each resting link solid pushed by the table, an arrow from its lowest
// point along the table normal (the sum of its contacts' forces, drawn at one
// place): a forearm lying on the table shows its load as an elbow does.
void add_link_forces(const Model& model, const Data& data, const PlaybackState& state,
                     Scene& scene, const SceneOptions& options) {
  for (std::size_t j = 0; j < state.links.size(); ++j) {
    const LinkContactSample& s = state.links[j];
    const double length = s.fn * options.force_scale;
    if (!s.resting || length <= 0) continue;
    const Eigen::Vector3d n = table_up(model, point_position(data, int(j), Eigen::Vector3d::Zero()));
    const std::optional<Eigen::Vector3d> point = link_contact_top(data, int(j), n);
    if (!point) continue;
    const double radius = std::max(kArrowRadius * model.links[j].radius, 0.002);
    scene.forces.push_back({*point, *point + length * n, radius, options.style.force, -1, int(j), s.fn});
  }
}

LineSet grid(const SceneOptions& options) {
  LineSet lines{{}, options.style.grid};
  const Eigen::AlignedBox2d& a = options.grid_area;
  if (a.isEmpty() || options.grid_spacing <= 0) return lines;
  const double h = options.grid_spacing, z = options.floor_z;
  for (double x = std::ceil(a.min().x() / h) * h; x <= a.max().x() + 1e-9; x += h)
    lines.points.insert(lines.points.end(), {{x, a.min().y(), z}, {x, a.max().y(), z}});
  for (double y = std::ceil(a.min().y() / h) * h; y <= a.max().y() + 1e-9; y += h)
    lines.points.insert(lines.points.end(), {{a.min().x(), y, z}, {a.max().x(), y, z}});
  return lines;
}

}  // namespace

Eigen::Vector3d table_up(const Model& model, const Eigen::Vector3d& point) {
  const Eigen::Vector3d up = world_up(model);
  if (model.table.empty()) return up;
  const TableBox* nearest = &model.table.front();
  for (const TableBox& box : model.table)
    if (distance_to_box(box, point) < distance_to_box(*nearest, point)) nearest = &box;
  // The face normal (+-column of the rotation) most aligned with up.
  Eigen::Vector3d best = nearest->rotation.col(2);
  for (int i = 0; i < 3; ++i)
    for (double sign : {1.0, -1.0}) {
      const Eigen::Vector3d n = sign * nearest->rotation.col(i);
      if (n.dot(up) > best.dot(up)) best = n;
    }
  return best;
}

Scene build_scene(const Model& model, const PlaybackState& state,
                  const std::vector<Eigen::Vector3d>& hand_path, const SceneOptions& options,
                  const std::vector<Eigen::Vector3d>& desired_path) {
  Data kinematics(model);
  return build_scene(model, kinematics, state, hand_path, options, desired_path);
}

Scene build_scene(const Model& model, Data& kinematics, const PlaybackState& state,
                  const std::vector<Eigen::Vector3d>& hand_path, const SceneOptions& options,
                  const std::vector<Eigen::Vector3d>& desired_path) {
  const SceneStyle& style = options.style;
  Data& data = kinematics;
  forward_kinematics(model, data, state.q);
  Scene scene;
  scene.background = style.background;
  for (const TableBox& box : model.table)
    scene.table.push_back({box.center, box.rotation, box.size, style.table});
  scene.base = base_plate(model, data, style);
  add_links(model, data, scene, style);
  add_elbows(model, data, state, scene, options);
  add_link_forces(model, data, state, scene, options);
  scene.hand_path = {hand_path, kPathRadius, style.hand_path};
  if (!desired_path.empty())
    scene.desired_hand_path = {desired_path, kDesiredRadius, style.desired_hand_path};
  scene.grid = grid(options);
  return scene;
}

Eigen::AlignedBox3d box_bounds(const Box& box) {
  Eigen::AlignedBox3d out;
  const Eigen::Vector3d half = 0.5 * (box.rotation.cwiseAbs() * box.size);
  out.extend(box.center - half);
  out.extend(box.center + half);
  return out;
}

Eigen::AlignedBox3d arm_bounds(const Scene& scene) {
  Eigen::AlignedBox3d out = box_bounds(scene.base);
  auto add = [&out](const Eigen::Vector3d& p, double r) {
    out.extend(p - Eigen::Vector3d::Constant(r));
    out.extend(p + Eigen::Vector3d::Constant(r));
  };
  for (const Capsule& c : scene.links) add(c.a, c.radius), add(c.b, c.radius);
  for (const Cylinder& c : scene.joints) add(c.a, c.radius), add(c.b, c.radius);
  for (const ElbowMarker& e : scene.elbows) add(e.sphere.center, e.sphere.radius);
  for (const Arrow& a : scene.forces) add(a.tip, a.radius);
  return out;
}

}  // namespace elbowsim

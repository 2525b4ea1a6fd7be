#include "engine/contact/detection.hpp"

#include <limits>

#include "engine/contact/collision.hpp"
#include "engine/contact/geometry.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

// One slot against its box, in closed form.
SlotContact measure(const Model& model, const Data& data, const ContactSlot& slot,
                    const Primitive& p) {
  const TableBox& box = model.table[slot.box];
  const Eigen::Vector3d a = data.origin[p.link] + data.rotation[p.link] * p.a;
  SlotContact s;
  Eigen::Vector3d centre = a;
  s.local = p.a;
  if (slot.part == ContactSlot::Part::end_b) {
    centre = data.origin[p.link] + data.rotation[p.link] * p.b;
    s.local = p.b;
  } else if (slot.part == ContactSlot::Part::interior) {
    // The segment's nearest point, when it is nearer than both ends (lying
    // across an edge); otherwise the ends' slots cover the segment.
    const Eigen::Vector3d b = data.origin[p.link] + data.rotation[p.link] * p.b;
    const double t = segment_box_parameter(a, b, box);
    const double ends = std::min(sphere_box(a, p.radius, box).distance,
                                 sphere_box(b, p.radius, box).distance);
    centre = a + t * (b - a);
    const BoxContact c = sphere_box(centre, p.radius, box);
    if (!(t > 1e-9 && t < 1 - 1e-9 && c.distance < ends - 1e-12)) {
      s.distance = kFar;
      return s;
    }
    s.local = p.a + t * (p.b - p.a);
  }
  const BoxContact c = sphere_box(centre, p.radius, box);
  s.near = true;
  s.distance = c.distance;
  s.normal = c.normal;
  s.point = c.point;
  s.feature = c.feature == BoxFeature::inside ? BoxFeature::face : c.feature;
  s.edge = c.edge;
  return s;
}

void measure_pair(const Model& model, Data& data, int pair) {
  ContactData& c = data.contact;
  const ContactGeometry& g = c.geometry;
  const int primitive = pair / g.boxes;
  for (int k = g.first_slot[pair]; k < g.first_slot[pair + 1]; ++k)
    c.detected[k] = measure(model, data, g.slots[k], g.primitives[primitive]);
}

}  // namespace

void detect_contacts(const Model& model, Data& data) {
  const StateLayout s(model);
  ContactData& c = data.contact;
  const ContactGeometry& g = c.geometry;
  const auto q = data.x.segment(s.q(), s.n);
  forward_kinematics(model, data, q);
  // Distances, normals and the near pairs depend on q alone: the detection
  // that ended the last step stands at the start of the next (unless an
  // impact's projection or a reset moved q).
  if (same_bits(q, c.detected_q)) return;
  c.detected_q = q;
  // Slots of the pairs near at the last detection go back to far; the others are.
  for (int pair : c.near_pairs)
    for (int k = g.first_slot[pair]; k < g.first_slot[pair + 1]; ++k) c.detected[k] = SlotContact{false, kFar};
  c.world->near_pairs(data, model.contact.detection_margin, c.near_pairs);
  // Elbows always (their distance to the table is recorded, near or not), the
  // links' solids where the broad phase found them near.
  const int elbow_pairs = static_cast<int>(model.elbows.size()) * g.boxes;
  for (int pair = 0; pair < elbow_pairs; ++pair) measure_pair(model, data, pair);
  for (int pair : c.near_pairs)
    if (pair >= elbow_pairs) measure_pair(model, data, pair);
}

void freeze_frames(Data& data) {
  ContactData& c = data.contact;
  for (int k = 0; k < c.slots(); ++k) {
    const SlotContact& d = c.detected[k];
    c.start_distance[static_cast<std::size_t>(k)] = d.near ? d.distance : std::numeric_limits<double>::infinity();
    if (!d.near) continue;
    c.normal[k] = d.normal;
    c.surface[k] = d.point;
    c.feature[k] = d.feature;
    c.edge[k] = d.edge;
  }
}

double feature_margin(const Model& model, const Data& data, int slot) {
  const ContactData& c = data.contact;
  const ContactSlot& s = c.slot(slot);
  const TableBox& box = model.table[static_cast<std::size_t>(s.box)];
  const Eigen::Vector3d h = 0.5 * box.size;
  const Eigen::Vector3d x = box.rotation.transpose() * (slot_centre(data, slot) - box.center);
  const Eigen::Vector3d on = box.rotation.transpose() * (c.surface[slot] - box.center);
  // The box axes the feature is clamped to (a face: its normal's; an edge: all but its own).
  bool clamped[3] = {true, true, true};
  Eigen::Index axis = 0;
  if (c.feature[slot] == BoxFeature::face) {
    (box.rotation.transpose() * c.normal[slot]).cwiseAbs().maxCoeff(&axis);
    clamped[0] = clamped[1] = clamped[2] = false;
    clamped[axis] = true;
  } else if (c.feature[slot] == BoxFeature::edge) {
    (box.rotation.transpose() * c.edge[slot]).cwiseAbs().maxCoeff(&axis);
    clamped[axis] = false;
  }
  // A ball of radius 0 sits on its feature's boundary by construction: only its
  // free axes can tell a change.
  const bool ball = c.primitive_of(slot).radius > 0 && c.feature[slot] != BoxFeature::face;
  double margin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (!clamped[i])
      margin = std::min(margin, h[i] - std::abs(x[i]));
    else if (ball)
      margin = std::min(margin, (on[i] >= 0 ? x[i] : -x[i]) - h[i]);
  }
  return margin;
}

double primitive_distance(const Model& model, const Data& data, const Primitive& p,
                          const TableBox& box) {
  (void)model;
  const Eigen::Vector3d a = data.origin[p.link] + data.rotation[p.link] * p.a;
  if (p.is_ball) return sphere_box(a, p.radius, box).distance;
  const Eigen::Vector3d b = data.origin[p.link] + data.rotation[p.link] * p.b;
  const double t = segment_box_parameter(a, b, box);
  return sphere_box(a + t * (b - a), p.radius, box).distance;
}

Eigen::Vector3d slot_centre(const Data& data, int slot) {
  const Primitive& p = data.contact.primitive_of(slot);
  return point_position(data, p.link, data.contact.detected[slot].local);
}

double normal_speed(const Model& model, const Data& data, int slot) {
  const StateLayout s(model);
  const Primitive& p = data.contact.primitive_of(slot);
  const Eigen::Vector3d v = point_velocity(data, p.link, data.contact.detected[slot].local,
                                           data.x.segment(s.qd(), s.n));
  return data.contact.detected[slot].normal.dot(v);
}

}  // namespace elbowsim

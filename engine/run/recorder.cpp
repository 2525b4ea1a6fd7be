#include "engine/run/recorder.hpp"

#include <algorithm>

#include <limits>

#include "engine/contact/detection.hpp"
#include "engine/control/controller.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

TrajectoryLayout trajectory_layout(const Model& model, bool desired_hand) {
  TrajectoryLayout::Groups g;
  g.dof = model.dof;
  g.motors = model.has_motor();
  g.desired_hand = desired_hand;
  g.contact = model.effects.contact;
  g.joint_friction = model.effects.joint_friction;
  g.gear = model.gear_losses;
  g.pads = model.has_pads();
  g.springs = model.has_springs();
  g.friction = model.effects.contact && model.effects.friction;
  if (g.contact)
    for (const Elbow& e : model.elbows) g.elbows.push_back(e.name);
  return TrajectoryLayout(std::move(g));
}

namespace {

void write_joints(const TrajectoryLayout& L, const Data& data, double* row) {
  for (int j = 0; j < L.dof(); ++j) {
    row[L.q(j)] = data.q[j];
    row[L.qd(j)] = data.qd[j];
    row[L.qdd(j)] = data.qdd[j];
    if (L.has_motors()) {
      row[L.current(j)] = data.current[j];
      row[L.voltage(j)] = data.voltage[j];
    }
    row[L.torque(j)] = data.actuation[j];
  }
}

// The hand, and where the plan wants it (linear between plan samples).
void write_hand(const Model& model, const TrajectoryLayout& L, const Data& data, double* row) {
  const Eigen::Vector3d hand = point_position(data, model.hand_link, model.hand_point);
  for (int a = 0; a < 3; ++a) row[L.hand(a)] = hand[a];
  if (!L.has_desired_hand() || !data.controller || !data.controller->plan) return;
  const Eigen::Vector3d desired = data.controller->plan->hand_at(data.t);
  for (int a = 0; a < 3; ++a) row[L.hand_desired(a)] = desired[a];
  row[L.hand_error()] = (hand - desired).norm();
}

// E_friction by body (state_layout.hpp: integrated with the motion).
void write_body_friction(const TrajectoryLayout& L, const Data& data, int first, double* row) {
  for (int k = 0; k < L.elbows(); ++k) row[L.elbow_friction(k)] = data.x[first + k];
  for (int j = 0; j < L.dof(); ++j) row[L.link_friction(j)] = data.x[first + L.elbows() + j];
}

// Per elbow over its slots (one per table box): the normal force (0 unless a
// row is on), the distance to the nearest box, resting on any. Per link, over
// its own solid's slots: the summed normal force, the nearest distance and
// resting on any. With friction, the friction loss at each body so far.
void write_contacts(const Model& model, const TrajectoryLayout& L, const Data& data, double* row) {
  const ContactData& c = data.contact;
  for (int k = 0; k < L.elbows(); ++k) {
    row[L.elbow_force(k)] = 0;
    row[L.elbow_distance(k)] = std::numeric_limits<double>::infinity();
    row[L.elbow_resting(k)] = 0;
  }
  for (int j = 0; j < L.dof(); ++j) {
    row[L.link_force(j)] = 0;
    row[L.link_distance(j)] = std::numeric_limits<double>::infinity();
    row[L.link_resting(j)] = 0;
  }
  for (int k = 0; k < c.slots(); ++k) {
    const Primitive& p = c.primitive_of(k);
    if (p.elbow < 0) {
      if (c.resting[k]) row[L.link_resting(p.link)] = 1.0;
      continue;
    }
    row[L.elbow_distance(p.elbow)] = std::min(row[L.elbow_distance(p.elbow)], c.detected[k].distance);
    if (c.resting[k]) row[L.elbow_resting(p.elbow)] = 1.0;
  }
  // A link's clearance: its whole solid (ends covered by an elbow's ball
  // included) to the nearest box, near or far (only at recorded samples).
  for (const Primitive& p : c.geometry.primitives) {
    if (p.elbow >= 0) continue;
    for (const TableBox& box : model.table)
      row[L.link_distance(p.link)] =
          std::min(row[L.link_distance(p.link)], primitive_distance(model, data, p, box));
  }
  for (std::size_t r = 0; r < c.active.size(); ++r) {
    const Primitive& p = c.primitive_of(c.active[r]);
    row[p.elbow >= 0 ? L.elbow_force(p.elbow) : L.link_force(p.link)] += c.fn[r];
  }
  if (L.has_body_friction()) write_body_friction(L, data, StateLayout(model).body_friction, row);
}

void write_energies(const TrajectoryLayout& L, const Data& data, double* row) {
  const EnergyTerms& e = data.energy;
  for (const EnergyTermInfo& t : kEnergyTerms)
    if (L.energy(t.term) >= 0) row[L.energy(t.term)] = e.*t.value;
  row[L.balance_residual()] = balance_residual(e, data.energy_initial);
}

}  // namespace

void record_sample(const Model& model, const Data& data, Recording& rec) {
  const TrajectoryLayout& L = rec.layout;
  const std::size_t start = rec.values.size();
  rec.values.resize(start + static_cast<std::size_t>(L.size()),
                    std::numeric_limits<double>::quiet_NaN());
  double* row = rec.values.data() + start;
  row[L.time()] = data.t;
  write_joints(L, data, row);
  write_hand(model, L, data, row);
  if (L.has_contact()) write_contacts(model, L, data, row);
  write_energies(L, data, row);
}

double recording_bytes_estimate(const Model& model, int every, bool desired_hand) {
  const double interval = model.options.step * std::max(every, 1);
  const double rows = std::min(model.options.duration / interval + 2, 1e18);
  return rows * double(trajectory_layout(model, desired_hand).columns().size()) * sizeof(double);
}

}  // namespace elbowsim

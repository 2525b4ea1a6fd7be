#include "engine/run/recorder.hpp"

#include <limits>

#include "engine/control/controller.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

TrajectoryLayout trajectory_layout(const Model& model, bool desired_hand) {
  TrajectoryLayout::Groups g;
  g.dof = model.dof;
  g.motors = model.has_motor();
  g.desired_hand = desired_hand;
  g.contact = model.effects.contact;
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

// Per elbow: normal force (0 unless its row is on), signed distance, resting flag.
void write_contacts(const TrajectoryLayout& L, const Data& data, double* row) {
  const ContactData& c = data.contact;
  for (int k = 0; k < L.elbows(); ++k) {
    double fn = 0;
    for (std::size_t r = 0; r < c.active.size(); ++r)
      if (c.active[r] == k) fn = c.fn[r];
    row[L.elbow_force(k)] = fn;
    row[L.elbow_distance(k)] = c.detected[k].distance;
    row[L.elbow_resting(k)] = c.resting[k] ? 1.0 : 0.0;
  }
}

void write_energies(const TrajectoryLayout& L, const Data& data, double* row) {
  const EnergyTerms& e = data.energy;
  const std::pair<Energy, double> terms[] = {
      {Energy::in, e.electrical_in},       {Energy::joule, e.joule},
      {Energy::viscous, e.viscous},        {Energy::kinetic_links, e.kinetic_links},
      {Energy::kinetic_rotors, e.kinetic_rotors}, {Energy::potential, e.potential},
      {Energy::magnetic, e.magnetic},      {Energy::friction, e.friction},
      {Energy::normal, e.normal_work},     {Energy::impact, e.impact_loss},
      {Energy::projection, e.projection}};
  for (const auto& [column, value] : terms)
    if (L.energy(column) >= 0) row[L.energy(column)] = value;
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
  if (L.has_contact()) write_contacts(L, data, row);
  write_energies(L, data, row);
}

}  // namespace elbowsim

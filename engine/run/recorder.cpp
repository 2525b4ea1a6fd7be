#include "engine/run/recorder.hpp"

#include <algorithm>

#include "engine/control/controller.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"

namespace elbowsim {

namespace {

void add_columns(std::vector<Column>& cols, const char* prefix, const char* unit, int n) {
  for (int j = 0; j < n; ++j) cols.push_back({prefix + std::to_string(j), unit});
}

}  // namespace

std::vector<Column> trajectory_columns(const Model& model, bool has_plan) {
  const int n = model.dof;
  std::vector<Column> cols{{"time", "s"}};
  add_columns(cols, "q", "rad", n);
  add_columns(cols, "qd", "rad/s", n);
  add_columns(cols, "qdd", "rad/s^2", n);
  if (model.has_motor()) {
    add_columns(cols, "i", "A", n);
    add_columns(cols, "v", "V", n);
  }
  add_columns(cols, "tau", "N m", n);
  for (const char* axis : {"hand_x", "hand_y", "hand_z"}) cols.push_back({axis, "m"});
  if (has_plan) {
    for (const char* axis : {"hand_d_x", "hand_d_y", "hand_d_z", "hand_error"}) cols.push_back({axis, "m"});
  }
  if (model.effects.contact) {
    for (const Elbow& e : model.elbows) {
      cols.push_back({"fn_" + e.name, "N"});
      cols.push_back({"d_" + e.name, "m"});
      cols.push_back({"rest_" + e.name, "1"});
    }
  }
  for (const char* e : {"E_in", "E_joule", "E_viscous", "KE_links", "KE_rotors", "PE",
                        "E_magnetic"})
    cols.push_back({e, "J"});
  if (model.effects.contact)
    for (const char* e : {"E_friction", "E_normal", "E_impact", "E_projection"})
      cols.push_back({e, "J"});
  cols.push_back({"balance_residual", "J"});
  return cols;
}

namespace {

// Per elbow: normal force (0 unless its row is on), signed distance, resting flag.
void append_contacts(const Model& model, const Data& data, std::vector<double>& row) {
  const ContactData& c = data.contact;
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    double fn = 0;
    for (std::size_t r = 0; r < c.active.size(); ++r)
      if (c.active[r] == k) fn = c.fn[r];
    row.insert(row.end(), {fn, c.detected[k].distance, c.resting[k] ? 1.0 : 0.0});
  }
}

void append(std::vector<double>& row, const Eigen::VectorXd& v) {
  row.insert(row.end(), v.data(), v.data() + v.size());
}

}  // namespace

void record_sample(const Model& model, const Data& data, Recording& rec) {
  std::vector<double>& row = rec.values;
  row.push_back(data.t);
  append(row, data.q);
  append(row, data.qd);
  append(row, data.qdd);
  if (model.has_motor()) {
    append(row, data.current);
    append(row, data.voltage);
  }
  append(row, data.actuation);
  const Eigen::Vector3d hand = point_position(data, model.hand_link, model.hand_point);
  row.insert(row.end(), {hand.x(), hand.y(), hand.z()});
  if (data.controller && data.controller->plan) {
    const Plan& plan = *data.controller->plan;
    const double u = std::clamp(data.t / plan.dt, 0.0, double(plan.hand.size() - 1));
    const std::size_t k = std::min(std::size_t(u), plan.hand.size() - 1);
    const std::size_t k1 = std::min(k + 1, plan.hand.size() - 1);
    const Eigen::Vector3d desired = plan.hand[k] + (u - double(k)) * (plan.hand[k1] - plan.hand[k]);
    row.insert(row.end(), {desired.x(), desired.y(), desired.z(), (hand - desired).norm()});
  }
  if (model.effects.contact) append_contacts(model, data, row);
  const EnergyTerms& e = data.energy;
  row.insert(row.end(), {e.electrical_in, e.joule, e.viscous, e.kinetic_links, e.kinetic_rotors,
                         e.potential, e.magnetic});
  if (model.effects.contact)
    row.insert(row.end(), {e.friction, e.normal_work, e.impact_loss, e.projection});
  row.push_back(balance_residual(e, data.energy_initial));
}

}  // namespace elbowsim

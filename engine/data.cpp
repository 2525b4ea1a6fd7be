#include "engine/data.hpp"

#include <limits>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/state_layout.hpp"

namespace elbowsim {

// llt is built in place: assigning an LLT copies its status before it has one.
namespace {

// Rows the run makes room for: contact.max_rows, or by default one per slot
// (three with Coulomb friction: a sticking slot's tangents) up to 2 dof +
// elbows + 4 (rows beyond dof are dependent: many balls flat on a face).
int contact_capacity(const Model& model, const ContactGeometry& g) {
  if (!model.effects.contact) return 0;  // no rows: a scene without contact pays for none
  const int rows = static_cast<int>(g.slots.size()) * (model.has_coulomb_friction() ? 3 : 1);
  if (model.contact.max_rows > 0) return std::min(model.contact.max_rows, rows);
  return std::min(rows, 2 * model.dof + static_cast<int>(model.elbows.size()) + 4);
}

ContactData make_contact_data(const Model& model) {
  ContactGeometry g = contact_geometry(model);
  const int capacity = contact_capacity(model, g);
  // The stick-slip LCP: at most 10 variables per 3 rows (a two-tangent cone: its
  // normal, 8 directions and its slip), 4 per 2 (one tangent).
  const int cones = model.has_coulomb_friction() ? 4 * capacity : 0;
  return ContactData(std::move(g), static_cast<int>(model.table.size()), model.dof, capacity,
                     cones);
}

}  // namespace

Data::Data(const Model& model) : llt(model.dof), contact(make_contact_data(model)) {
  const int n = model.dof;
  const auto un = static_cast<std::size_t>(n);
  q = qd = current = qdd = voltage = current_rate = actuation = Eigen::VectorXd::Zero(n);
  joint_mode.assign(static_cast<std::size_t>(n), 0);
  joint_friction_torque = tau_applied = Eigen::VectorXd::Zero(n);
  joint_mass = Eigen::MatrixXd::Zero(n, n);
  rotation.assign(un, Eigen::Matrix3d::Identity());
  origin.assign(un, Eigen::Vector3d::Zero());
  kinematics_q = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
  bias_rates_qd = Eigen::VectorXd::Zero(n);
  axis = com = omega = omega_dot = origin_acc = force = moment = origin;
  inertia = rotation;
  mass_matrix = Eigen::MatrixXd::Zero(n, n);
  bias = tau = zero = unit = D = u = D_inv = coupling = Eigen::VectorXd::Zero(n);
  spatial_inertia.assign(un, Matrix6d::Zero());
  articulated_inertia = spatial_inertia;
  motion_subspace.assign(un, Vector6d::Zero());
  velocity = bias_acc = bias_force = acc = U = U_over_D = motion_subspace;
  q_desired = qd_desired = v_feedforward = Eigen::VectorXd::Zero(n);
  // A step emits at most a landing and a release per elbow per stage, and a
  // warning per link-box pair plus one for dependent rows.
  log.events.reserve(4 * contact.geometry.slots.size() + 4);
  log.warnings.reserve(4);
  const int m = StateLayout(model).size;
  model_id = model.id;
  dof = n;
  state_size = m;
  x = x_start = k1 = k2 = k3 = k4 = x_a = x_b = x_c = Eigen::VectorXd::Zero(m);
  lambda = Eigen::ArrayXd::Zero(m);
  adaptive.k5 = adaptive.k6 = adaptive.k7 = adaptive.f0 = adaptive.dfdt = adaptive.error = adaptive.x_saved = x;
  adaptive.dense = Eigen::MatrixXd::Zero(m, 5);
  adaptive.jacobian = adaptive.w = Eigen::MatrixXd::Zero(m, m);
  adaptive.lu = Eigen::PartialPivLU<Eigen::MatrixXd>(m);
  for (EtdCoefficients* c : {&etd_full, &etd_short})
    c->exp_h = c->exp_half = c->phi1_half = c->phi1_h = c->f1 = c->f2 = c->f3 = lambda;
}

void check_data(const Model& model, const Data& data) {
  auto differs = [&](const char* what, long made_for, long given) {
    if (made_for == given) return;
    throw std::invalid_argument("Data made for another model: " + std::string(what) + " " +
                                std::to_string(made_for) + " (Data) vs " + std::to_string(given) +
                                " (model '" + model.name + "')");
  };
  differs("model id", data.model_id, model.id);
  differs("dof", data.dof, model.dof);
  differs("state size", data.state_size, StateLayout(model).size);
  long elbows = 0;
  for (const Primitive& p : data.contact.geometry.primitives) elbows += p.elbow >= 0;
  differs("elbows", elbows, static_cast<long>(model.elbows.size()));
}

}  // namespace elbowsim

#include "engine/contact/stick_slip.hpp"

#include <cmath>

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/friction.hpp"
#include "engine/contact/friction_lcp.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

constexpr double kForceTolerance = 1e-9;  // [N] as a release (events.cpp)

ConstVec rates(const Model& model, const Data& data) {
  const StateLayout s(model);
  return data.x.segment(s.qd(), s.n);
}

int normal_row_of(const ContactData& c, int slot) {
  for (int r = 0; r < c.normal_rows(); ++r)
    if (c.active[static_cast<std::size_t>(r)] == slot) return r;
  return -1;
}

// Whether candidate k may stick: it sticks, or its slip has stopped (a stop
// was located, or it turned faster than stick_velocity), or it is a new
// contact whose point moves slower than that. A slip that has just started is
// as slow as one that stops; only the located stop tells them apart, so a
// slow slip goes on (no chatter at the cone's edge, where the speed's sign is
// rounding). A slip that goes on updates its direction.
bool may_stick(const Model& model, Data& data, int k, ConstVec qd) {
  ContactData& c = data.contact;
  const Eigen::Vector3d v_t = tangential_velocity(data, k, c.normal[k], qd);
  const double speed = v_t.norm(), slow = model.contact.friction.stick_velocity;
  const bool stopped = c.slip_stopped[k] || c.slip[k].dot(v_t) < -slow;
  c.slip_stopped[k] = 0;
  const bool stick = c.resting[k] ? c.sticking[k] || stopped : speed <= slow;
  if (!stick && speed > slow) c.slip[k] = v_t / speed;
  return stick;
}

// The modes carried over hold at the step's start: every candidate rested and
// keeps its mode, normal forces >= 0 and sticking forces inside their cones.
bool modes_hold(const Model& model, Data& data, ConstVec qd) {
  ContactData& c = data.contact;
  for (int k : c.candidates)
    if (!c.resting[k] || c.may_stick[k] != c.sticking[k]) return false;
  c.active = c.candidates;
  tangent_rows_from_modes(model, data);
  if (c.normal_rows() + static_cast<int>(c.tangent_rows.size()) > c.capacity()) return false;
  constraint_rows(model, data, qd);
  solve_constrained(model, data, data.tau_applied);
  for (int r = 0; r < c.normal_rows(); ++r) {
    const int k = c.active[static_cast<std::size_t>(r)];
    if (c.fn[r] < -kForceTolerance) return false;
    if (c.sticking[k] && cone_margin(model, data, k) < -kForceTolerance) return false;
  }
  return true;
}

void fail(Data& data, Failure::Kind kind, double value = 0, double limit = 0) {
  data.failure = Failure{kind, data.t, data.step_count};
  data.failure.value = value;
  data.failure.limit = limit;
}

// The direction a newly slipping contact slips in: its tangential acceleration
// at the LCP's solution (row accelerations in c.lcp_w), else against its force.
Eigen::Vector3d new_slip(const Model& model, const ContactData& c, const FrictionCone& cone) {
  Eigen::Vector3d t[2];
  tangent_basis(model, c.row_normal.col(cone.normal_row), t[0], t[1]);
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), f = Eigen::Vector3d::Zero();
  for (int j = 0; j < cone.tangents; ++j) {
    a += c.lcp_w[cone.tangent_row + j] * t[j];
    f += c.lcp_f[cone.tangent_row + j] * t[j];
  }
  if (a.norm() > 0) return a.normalized();
  return f.norm() > 0 ? Eigen::Vector3d(-f.normalized()) : t[0];
}

// Stewart and Trinkle's LCP over every candidate: normal rows (slipping ones
// with their friction), cones for those that may stick.
bool solve_modes(const Model& model, Data& data, ConstVec qd) {
  ContactData& c = data.contact;
  c.active = c.candidates;
  for (int k : c.candidates) c.sticking[k] = c.may_stick[k];
  tangent_rows_from_modes(model, data);
  const int cn = c.normal_rows();
  const int rows = cn + static_cast<int>(c.tangent_rows.size());
  if (rows > c.capacity()) {
    fail(data, Failure::Kind::too_many_contacts, rows, c.capacity());
    return false;
  }
  constraint_rows(model, data, qd);
  contact_lcp_terms(model, data, data.tau_applied);
  c.cones.cones.clear();
  bool slipping = false;
  for (std::size_t i = 0; i < c.tangent_rows.size(); ++i) {
    const TangentRow& t = c.tangent_rows[i];
    if (t.axis == 0)
      c.cones.cones.push_back({t.normal_row, cn + static_cast<int>(i), 1, model.contact.friction.mu});
    else
      c.cones.cones.back().tangents = 2;
  }
  for (int k : c.candidates) slipping = slipping || !c.may_stick[k];
  const auto cones = static_cast<Eigen::Index>(c.cones.cones.size());
  const FrictionLcpResult lcp =
      solve_friction_lcp(c.A, c.lcp_b, cn, c.cones, c.lcp_f, c.cone_slip.head(cones));
  if (!lcp.solved) {
    fail(data, slipping ? Failure::Kind::painleve : Failure::Kind::no_contact_solution);
    return false;
  }
  c.lcp_w.noalias() = c.A * c.lcp_f;
  c.lcp_w += c.lcp_b;
  const double force_tol = 1e-10 * std::max(c.lcp_f.head(cn).cwiseAbs().maxCoeff(), 1e-300);
  c.lcp_active.assign(c.candidates.size(), false);
  for (int r = 0; r < cn; ++r) c.lcp_active[static_cast<std::size_t>(r)] = c.lcp_f[r] > force_tol;
  const double slip_tol = 1e-10 * c.lcp_b.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < cones; ++i) {
    const FrictionCone& cone = c.cones.cones[static_cast<std::size_t>(i)];
    const int k = c.candidates[static_cast<std::size_t>(cone.normal_row)];
    // sigma is the slip's acceleration; below 1e-10 of the largest free row
    // acceleration it is the pivoting's rounding (dependent rows give 1e-15),
    // not a slip. A slip that was located to start needs no LCP (may_stick).
    if (c.cone_slip[i] <= slip_tol) continue;
    c.sticking[k] = 0;
    c.slip[k] = new_slip(model, c, cone);
  }
  return true;
}

// Stick and slip events of the slots that rest before and after.
void log_mode_changes(Data& data, ConstVec qd) {
  ContactData& c = data.contact;
  for (std::size_t r = 0; r < c.candidates.size(); ++r) {
    const int k = c.candidates[r];
    if (!c.resting[k] || !c.lcp_active[r] || c.was_sticking[k] == c.sticking[k]) continue;
    ContactEvent e{data.t, k, c.sticking[k] ? ContactEvent::Kind::stick : ContactEvent::Kind::slip, 0, 0, 0};
    if (c.sticking[k]) e.speed = tangential_velocity(data, k, c.normal[k], qd).norm();
    data.log.events.push_back(e);
  }
}

}  // namespace

bool decide_stick_slip(const Model& model, Data& data) {
  ContactData& c = data.contact;
  const ConstVec qd = rates(model, data);
  for (int k : c.candidates) {
    c.was_sticking[k] = c.resting[k] ? c.sticking[k] : 0;
    c.may_stick[k] = may_stick(model, data, k, qd);
  }
  if (modes_hold(model, data, qd)) {
    c.lcp_active.assign(c.candidates.size(), true);
    return true;
  }
  if (!solve_modes(model, data, qd)) return false;
  log_mode_changes(data, qd);
  return true;
}

void tangent_rows_from_modes(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.tangent_rows.clear();
  if (!model.has_coulomb_friction()) return;
  for (int r = 0; r < c.normal_rows(); ++r) {
    const int k = c.active[static_cast<std::size_t>(r)];
    if (!c.sticking[k]) continue;
    Eigen::Vector3d t1, t2;
    const int tangents = tangent_basis(model, c.normal[k], t1, t2);
    for (int axis = 0; axis < tangents; ++axis) c.tangent_rows.push_back({k, r, axis});
  }
}

Eigen::Vector3d friction_force(const Model& model, const Data& data, int slot) {
  const ContactData& c = data.contact;
  const int r = normal_row_of(c, slot);
  if (r < 0) return Eigen::Vector3d::Zero();
  Eigen::Vector3d f = c.fn[r] * c.row_friction.col(r);
  Eigen::Vector3d t[2];
  tangent_basis(model, c.row_normal.col(r), t[0], t[1]);
  for (std::size_t i = 0; i < c.tangent_rows.size(); ++i)
    if (c.tangent_rows[i].slot == slot)
      f += c.fn[c.normal_rows() + static_cast<Eigen::Index>(i)] * t[c.tangent_rows[i].axis];
  return f;
}

double cone_margin(const Model& model, const Data& data, int slot) {
  const int r = normal_row_of(data.contact, slot);
  if (r < 0) return 0;
  return model.contact.friction.mu * data.contact.fn[r] - friction_force(model, data, slot).norm();
}

double slip_speed(const Model& model, const Data& data, int slot) {
  const ContactData& c = data.contact;
  const int r = normal_row_of(c, slot);
  const Eigen::Vector3d n = r >= 0 ? Eigen::Vector3d(c.row_normal.col(r)) : c.normal[slot];
  const Eigen::Vector3d v_t = tangential_velocity(data, slot, n, rates(model, data));
  Eigen::Vector3d t1, t2;
  if (tangent_basis(model, n, t1, t2) == 1) return (c.slip[slot].dot(t1) >= 0 ? 1.0 : -1.0) * t1.dot(v_t);
  return c.slip[slot].dot(v_t);
}

}  // namespace elbowsim

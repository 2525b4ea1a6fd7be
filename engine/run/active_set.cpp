#include "engine/run/active_set.hpp"

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/contact/detection.hpp"
#include "engine/contact/lcp.hpp"
#include "engine/contact/pad.hpp"
#include "engine/contact/stick_slip.hpp"
#include "engine/control/controller.hpp"
#include "engine/dynamics/applied_torques.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/motor.hpp"
#include "engine/dynamics/walker_orin.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

// Mass matrix, bias and applied torques (data.tau_applied) at the state in data.x.
void prepare_mechanics(const Model& model, Data& data) {
  const StateLayout s(model);
  const auto qd = data.x.segment(s.qd(), s.n);
  command(model, data, data.t, data.x.segment(s.q(), s.n), qd);
  if (s.current >= 0)
    motor_stage(model, data, qd, data.x.segment(s.current, s.n));
  else
    motor_stage(model, data, qd, data.current);
  applied_torques(model, data, qd);
  constrained_mechanics(model, data, qd);
}

// Whether slot k's row n^T J can move it along the normal at all: a ball whose
// point moves only sideways (a hanging link's tip, in this pose) has a zero
// row, which can neither be pushed nor carry a force.
bool movable(const Model& model, Data& data, int k) {
  ContactData& c = data.contact;
  point_jacobian(model, data, c.primitive_of(k).link, c.detected[k].local, c.J3);
  double row = 0;
  for (Eigen::Index j = 0; j < c.J3.cols(); ++j) row = std::max(row, std::abs(c.normal[k].dot(c.J3.col(j))));
  return row > 1e-12;  // [m/rad]
}

// Slots at or into the table and not separating, and those already resting;
// not those whose row is zero (they rest without a row).
void touching_slots(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.candidates.clear();
  for (int k = 0; k < c.slots(); ++k) {
    // A pad touches where it presses (pad.hpp): above it, its k d + c d' means nothing.
    const bool touching =
        c.resting[k] || (slot_pad(model, c, k)
                             ? pad_presses(model, data, k)
                             : c.detected[k].distance <= model.contact.touch_distance &&
                                   normal_speed(model, data, k) <= model.contact.separation_velocity);
    if (!touching) continue;
    if (movable(model, data, k)) {
      c.candidates.push_back(k);
    } else if (c.resting[k]) {
      book_pad_release(model, data, k);
      c.resting[k] = 0;  // off quietly: it carried nothing
    }
  }
}

// Warns once per run about dependent rows, with their rank.
void warn_dependent(const Model& model, Data& data) {
  ContactData& c = data.contact;
  ++c.dependent_steps;
  if (c.dependent_warned) return;
  SolverWorkspace& ws = c.solver(c.rows());
  ws.rows_rank.compute(c.Jc);
  ws.rows_rank.setThreshold(model.contact.rank_tolerance);
  Warning w;
  w.kind = Warning::Kind::dependent_rows;
  w.t = data.t;
  w.count = c.rows();
  w.rank = static_cast<int>(ws.rows_rank.rank());
  data.log.warnings.push_back(w);
  c.dependent_warned = true;
}

// Switches rows on and off as the LCP decided, with their events.
void apply_decision(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.active.clear();
  for (std::size_t r = 0; r < c.candidates.size(); ++r) {
    const int k = c.candidates[r];
    const bool on = c.lcp_active[r];
    if (on) {
      c.active.push_back(k);
      if (!c.resting[k]) pad_contact_begins(model, data, k);
      if (!c.resting[k])
        data.log.events.push_back({data.t, k, ContactEvent::Kind::landing,
                                   std::max(0.0, -normal_speed(model, data, k)), 0, 0});
    } else if (c.resting[k]) {
      book_pad_release(model, data, k);
      data.log.events.push_back({data.t, k, ContactEvent::Kind::release, 0, 0, 0});
    }
    c.resting[k] = on;
  }
}

void fail(Data& data, Failure::Kind kind) {
  data.failure.kind = kind;
  data.failure.t = data.t;
  data.failure.step = data.step_count;
}

}  // namespace

bool select_active_set(const Model& model, Data& data) {
  ContactData& c = data.contact;
  detect_contacts(model, data);
  freeze_frames(data);
  if (model.has_pads())  // a released pad's slot starts from its pad's surface
    for (int k = 0; k < c.slots(); ++k)
      c.start_distance[static_cast<std::size_t>(k)] += pad_surface_depth(model, c, k, data.t);
  touching_slots(model, data);
  c.tangent_rows.clear();
  if (static_cast<int>(c.candidates.size()) > c.capacity()) {
    data.failure = Failure{Failure::Kind::too_many_contacts, data.t, data.step_count};
    data.failure.value = static_cast<double>(c.candidates.size());
    data.failure.limit = c.capacity();
    return false;
  }
  c.active = c.candidates;
  if (c.candidates.empty()) return true;

  prepare_mechanics(model, data);
  if (model.has_coulomb_friction()) {
    if (!decide_stick_slip(model, data)) return false;
    if (c.dependent) warn_dependent(model, data);
    apply_decision(model, data);
    tangent_rows_from_modes(model, data);
    return true;
  }
  const StateLayout s(model);
  constraint_rows(model, data, data.x.segment(s.qd(), s.n));
  contact_lcp_terms(model, data, data.tau_applied);
  if (model.effects.friction && (c.A.diagonal().array() <= 0).any()) {
    fail(data, Failure::Kind::painleve);
    return false;
  }
  // Dependent rows make the forces non-unique: start from all rows on, so the
  // minimum-norm split is kept whenever it is complementary. The Schur solve
  // above already checked the rank of M~ = Jc M^-1 Jc^T (pivots against
  // rank_tolerance), so no second factorisation here.
  const bool dependent = c.dependent;
  c.lcp_active.assign(c.candidates.size(), true);
  if (!dependent)
    for (std::size_t r = 0; r < c.candidates.size(); ++r)
      c.lcp_active[r] = c.resting[c.candidates[r]];
  const LcpResult lcp = solve_lcp(c.A, c.lcp_b, model.contact.rank_tolerance, 1e-9, c.lcp_f,
                                  c.lcp_w, c.lcp_active, LcpScratch{c.solvers, c.lcp_index, &c.lemke});
  if (!lcp.solved) {
    fail(data, Failure::Kind::no_contact_solution);
    return false;
  }
  if (dependent || lcp.dependent) warn_dependent(model, data);
  apply_decision(model, data);
  return true;
}

}  // namespace elbowsim

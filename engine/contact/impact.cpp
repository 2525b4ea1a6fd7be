#include "engine/contact/impact.hpp"

#include "engine/contact/detection.hpp"
#include "engine/contact/friction.hpp"
#include "engine/contact/lcp.hpp"
#include "engine/contact/pad.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

// The rows of the slots in data.contact.impact_rows, into ws.Jc: first their
// normal rows n_k^T J_k, then (Coulomb friction) the tangent rows t^T J_pk of
// their contact points. Returns the number of rows, or -1 beyond the workspace.
int impact_jacobian(const Model& model, Data& data, int m) {
  ContactData& c = data.contact;
  const bool cones = model.has_coulomb_friction();
  int rows = m;
  if (cones) {
    for (int k : c.impact_rows) {
      Eigen::Vector3d t1, t2;
      rows += tangent_basis(model, c.detected[k].normal, t1, t2);
    }
  }
  if (rows > c.capacity()) return -1;
  SolverWorkspace& ws = c.solver(rows);
  c.cones.cones.clear();
  int tangent = m;
  for (int r = 0; r < m; ++r) {
    const int k = c.impact_rows[static_cast<std::size_t>(r)];
    const Eigen::Vector3d& n = c.detected[k].normal;
    const int link = c.primitive_of(k).link;
    point_jacobian(model, data, link, c.detected[k].local, c.J3);
    for (Eigen::Index j = 0; j < c.J3.cols(); ++j) ws.Jc(r, j) = n.dot(c.J3.col(j));
    if (!cones) continue;
    Eigen::Vector3d t[2];
    const int tangents = tangent_basis(model, n, t[0], t[1]);
    point_jacobian(model, data, link, contact_point_local(data, k, n), c.J3);
    for (int a = 0; a < tangents; ++a)
      for (Eigen::Index j = 0; j < c.J3.cols(); ++j) ws.Jc(tangent + a, j) = t[a].dot(c.J3.col(j));
    c.cones.cones.push_back({r, tangent, tangents, model.contact.friction.mu});
    tangent += tangents;
  }
  return rows;
}

double kinetic_energy(Data& data, ConstVec qd) {
  data.tau.noalias() = data.mass_matrix * qd;
  return 0.5 * qd.dot(data.tau);
}

// After an impact with Coulomb friction: a contact whose point no longer slips
// sticks; the others slip the way they move.
void modes_after_impact(const Model& model, Data& data, ConstVec qd) {
  ContactData& c = data.contact;
  for (int k : c.impact_rows) {
    const Eigen::Vector3d v_t = tangential_velocity(data, k, c.detected[k].normal, qd);
    const double speed = v_t.norm();
    c.sticking[k] = speed <= model.contact.friction.stick_velocity;
    if (!c.sticking[k]) c.slip[k] = v_t / speed;
  }
}

ImpactResult unsolved(ContactData& c) {
  SolverWorkspace& none = c.solver(0);
  return ImpactResult{none.impulse, none.speed_before, none.speed_after, none.energy_lost, 0, 0, false};
}

// Whether a landing row would rebound, but slower than settle_speed.
bool settles(const Model& model, const ContactData& c, const ImpactResult& r) {
  const double settle = settle_speed(model);
  for (std::size_t row = 0; row < c.landing.size(); ++row) {
    const double rebound = r.speed_after[static_cast<Eigen::Index>(row)];
    if (rebound > model.contact.separation_velocity && rebound < settle) return true;
  }
  return false;
}

// The impact's loss and events; rows in c.impact_rows order (the landing
// slots, then the resting ones). A row left separating is released.
void record_impact(const Model& model, Data& data, const ImpactResult& r) {
  ContactData& c = data.contact;
  if (!r.solved) {
    // No impulse meets the cones and the normal complementarity (or the rows
    // exceed the run's room): the run cannot go on honestly.
    data.failure = Failure{Failure::Kind::no_contact_solution, data.t, data.step_count};
    return;
  }
  c.impact_loss += r.kinetic_before - r.kinetic_after;
  for (std::size_t row = 0; row < c.impact_rows.size(); ++row) {
    const auto i = static_cast<Eigen::Index>(row);
    const int k = c.impact_rows[row];
    const bool lands = row < c.landing.size();
    if (lands)
      data.log.events.push_back({data.t, k, ContactEvent::Kind::landing, -r.speed_before[i], r.impulse[i],
                                 r.energy_lost[i]});
    // A row that rested before the impact and is left leaving slower than
    // settle_speed stays resting: the next step's active set decides it at
    // acceleration level (and its drift control takes the speed out). Two
    // contacts of one arm (an elbow and the hand) otherwise rock each other
    // off at ever smaller speeds, each landing lifting the other (Zeno: the
    // experiment's hold task stalled at 9e-6 s per 10 000 steps).
    const bool settles = !lands && r.speed_after[i] < settle_speed(model);
    const bool separating = r.speed_after[i] > model.contact.separation_velocity && !settles;
    if (separating && (lands || c.resting[k]))
      data.log.events.push_back({data.t, k, ContactEvent::Kind::release, 0, 0, 0});
    c.resting[k] = !separating;
  }
}

}  // namespace

ImpactResult apply_impact(const Model& model, Data& data, const std::vector<int>& landing,
                          const std::vector<int>& resting, double restitution) {
  const StateLayout s(model);
  ContactData& c = data.contact;
  c.impact_rows.assign(landing.begin(), landing.end());
  c.impact_rows.insert(c.impact_rows.end(), resting.begin(), resting.end());
  const int m = static_cast<int>(c.impact_rows.size());
  auto qd = data.x.segment(s.qd(), s.n);
  mass_matrix_crba(model, data);
  data.llt.compute(data.mass_matrix);
  const int rows = impact_jacobian(model, data, m);
  if (rows < 0) return unsolved(c);
  SolverWorkspace& ws = c.solver(rows);
  ws.MinvJt = ws.Jc.transpose();
  data.llt.solveInPlace(ws.MinvJt);
  ws.A.noalias() = ws.Jc * ws.MinvJt;
  ws.speed_before.noalias() = ws.Jc * qd;
  ws.b = ws.speed_before;
  for (std::size_t k = 0; k < landing.size(); ++k) ws.b[k] *= 1.0 + restitution;
  const double kinetic_before = kinetic_energy(data, qd);
  bool solved;
  if (model.has_coulomb_friction()) {
    solved = solve_friction_lcp(ws.A, ws.b, m, c.cones, ws.impulse,
                                c.cone_slip.head(static_cast<Eigen::Index>(c.cones.cones.size())))
                 .solved;
  } else {
    c.lcp_active.assign(static_cast<std::size_t>(m), true);
    solved = solve_lcp(ws.A, ws.b, model.contact.rank_tolerance, 1e-12, ws.impulse, ws.w,
                       c.lcp_active, LcpScratch{c.solvers, c.lcp_index, &c.lemke})
                 .solved;
  }
  if (!solved) return unsolved(c);
  ws.dx.noalias() = ws.MinvJt * ws.impulse;
  qd += ws.dx;
  ws.speed_after.noalias() = ws.Jc * qd;
  // Each row's share of the kinetic energy lost; a contact's tangent rows add to its normal row's.
  ws.energy_lost = -0.5 * ws.impulse.cwiseProduct(ws.speed_before + ws.speed_after);
  for (const FrictionCone& cone : c.cones.cones) {
    if (!model.has_coulomb_friction()) break;
    for (int a = 0; a < cone.tangents; ++a) ws.energy_lost[cone.normal_row] += ws.energy_lost[cone.tangent_row + a];
  }
  if (model.has_coulomb_friction()) modes_after_impact(model, data, qd);
  return ImpactResult{ws.impulse.head(m), ws.speed_before.head(m), ws.speed_after.head(m),
                      ws.energy_lost.head(m), kinetic_before, kinetic_energy(data, qd), true};
}

void land_touching_slots(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.landing.clear();
  const double limit = model.contact.events == EventTiming::locate ? model.contact.touch_distance : 0.0;
  // Approaching faster than contact.separation_velocity: slower is no impact (and a
  // row that cannot move along the normal approaches only by rounding).
  // A padded slot lands without an impulse (its pad's force is finite): it
  // rests, and the next step's start decides its row with the others.
  auto land_softly = [&](int k) {
    pad_contact_begins(model, data, k);
    data.log.events.push_back({data.t, k, ContactEvent::Kind::landing, -normal_speed(model, data, k), 0, 0});
    c.resting[k] = true;
    c.sticking[k] = 0;  // the next step's start decides (stick_slip.hpp)
  };
  // A pad lands where it presses (pad.hpp): above it, its k d + c d' means nothing.
  for (int k = 0; k < c.slots(); ++k) {
    if (c.resting[k]) continue;
    if (slot_pad(model, c, k)) {
      if (pad_presses(model, data, k)) land_softly(k);
    } else if (c.detected[k].distance <= limit &&
               normal_speed(model, data, k) < -model.contact.separation_velocity) {
      c.landing.push_back(k);
    }
  }
  if (c.landing.empty()) return;
  if (!model.effects.impacts) {
    for (int k : c.landing) land_softly(k);
    return;
  }
  c.candidates.clear();  // the rigid slots already resting (a pad takes no impulse)
  for (int k = 0; k < c.slots(); ++k)
    if (c.resting[k] && !slot_pad(model, c, k)) c.candidates.push_back(k);
  if (static_cast<int>(c.landing.size() + c.candidates.size()) > c.capacity()) {
    data.failure = Failure{Failure::Kind::too_many_contacts, data.t, data.step_count};
    data.failure.value = static_cast<double>(c.landing.size() + c.candidates.size());
    data.failure.limit = c.capacity();
    return;
  }
  const StateLayout s(model);
  auto qd = data.x.segment(s.qd(), s.n);
  c.qd_before_impact = qd;
  const ImpactResult r = apply_impact(model, data, c.landing, c.candidates, model.contact.restitution);
  if (!r.solved || !settles(model, c, r)) return record_impact(model, data, r);
  qd = c.qd_before_impact;
  record_impact(model, data, apply_impact(model, data, c.landing, c.candidates, 0.0));
}

double settle_speed(const Model& model) {
  if (model.contact.settle_speed >= 0) return model.contact.settle_speed;
  return model.effects.gravity ? model.gravity.norm() * model.options.step : 0.0;
}

}  // namespace elbowsim

#include "engine/contact/impact.hpp"

#include "engine/contact/detection.hpp"
#include "engine/contact/lcp.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/state_layout.hpp"

namespace elbowsim {

namespace {

// The rows n_k^T J_k of the slots in data.contact.impact_rows, into ws.Jc.
void normal_rows(const Model& model, Data& data, SolverWorkspace& ws) {
  ContactData& c = data.contact;
  for (std::size_t r = 0; r < c.impact_rows.size(); ++r) {
    const int k = c.impact_rows[r];
    point_jacobian(model, data, c.primitive_of(k).link, c.detected[k].local, c.J3);
    for (Eigen::Index j = 0; j < c.J3.cols(); ++j)
      ws.Jc(static_cast<Eigen::Index>(r), j) = c.normal[k].dot(c.J3.col(j));
  }
}

double kinetic_energy(Data& data, ConstVec qd) {
  data.tau.noalias() = data.mass_matrix * qd;
  return 0.5 * qd.dot(data.tau);
}

}  // namespace

ImpactResult apply_impact(const Model& model, Data& data, const std::vector<int>& landing,
                          const std::vector<int>& resting) {
  const StateLayout s(model);
  ContactData& c = data.contact;
  c.impact_rows.assign(landing.begin(), landing.end());
  c.impact_rows.insert(c.impact_rows.end(), resting.begin(), resting.end());
  const int m = static_cast<int>(c.impact_rows.size());
  SolverWorkspace& ws = c.solver(m);
  auto qd = data.x.segment(s.qd(), s.n);
  mass_matrix_crba(model, data);
  data.llt.compute(data.mass_matrix);
  normal_rows(model, data, ws);
  ws.MinvJt = ws.Jc.transpose();
  data.llt.solveInPlace(ws.MinvJt);
  ws.A.noalias() = ws.Jc * ws.MinvJt;
  ws.speed_before.noalias() = ws.Jc * qd;
  ws.b = ws.speed_before;
  for (std::size_t k = 0; k < landing.size(); ++k) ws.b[k] *= 1.0 + model.contact.restitution;
  c.lcp_active.assign(static_cast<std::size_t>(m), true);
  const double kinetic_before = kinetic_energy(data, qd);
  const bool solved = solve_lcp(ws.A, ws.b, model.contact.rank_tolerance, 1e-12, ws.impulse, ws.w,
                                c.lcp_active, LcpScratch{c.solvers, c.lcp_index, &c.lemke})
                          .solved;
  ws.dx.noalias() = ws.MinvJt * ws.impulse;
  qd += ws.dx;
  ws.speed_after.noalias() = ws.Jc * qd;
  ws.energy_lost = -0.5 * ws.impulse.cwiseProduct(ws.speed_before + ws.speed_after);
  return ImpactResult{ws.impulse,     ws.speed_before, ws.speed_after, ws.energy_lost,
                      kinetic_before, kinetic_energy(data, qd), solved};
}

void land_touching_slots(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.landing.clear();
  const double limit = model.contact.events == EventTiming::locate ? model.contact.touch_distance : 0.0;
  // Approaching faster than contact.separation_velocity: slower is no impact (and a
  // row that cannot move along the normal approaches only by rounding).
  for (int k = 0; k < c.slots(); ++k)
    if (!c.resting[k] && c.detected[k].distance <= limit &&
        normal_speed(model, data, k) < -model.contact.separation_velocity)
      c.landing.push_back(k);
  if (c.landing.empty()) return;
  if (!model.effects.impacts) {
    for (int k : c.landing) {
      data.log.events.push_back({data.t, k, ContactEvent::Kind::landing, -normal_speed(model, data, k), 0, 0});
      c.resting[k] = true;
    }
    return;
  }
  c.candidates.clear();  // the slots already resting
  for (int k = 0; k < c.slots(); ++k)
    if (c.resting[k]) c.candidates.push_back(k);
  if (static_cast<int>(c.landing.size() + c.candidates.size()) > c.capacity()) {
    data.failure = Failure{Failure::Kind::too_many_contacts, data.t, data.step_count};
    data.failure.value = static_cast<double>(c.landing.size() + c.candidates.size());
    data.failure.limit = c.capacity();
    return;
  }
  const ImpactResult r = apply_impact(model, data, c.landing, c.candidates);
  c.impact_loss += r.kinetic_before - r.kinetic_after;
  for (std::size_t row = 0; row < c.landing.size(); ++row) {
    const auto i = static_cast<Eigen::Index>(row);
    data.log.events.push_back({data.t, c.landing[row], ContactEvent::Kind::landing,
                               -r.speed_before[i], r.impulse[i], r.energy_lost[i]});
    c.resting[c.landing[row]] = true;
  }
}

}  // namespace elbowsim

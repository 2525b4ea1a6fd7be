#include "engine/contact/contact_tracker.hpp"

#include <Eigen/QR>
#include <sstream>

#include "engine/contact/constrained_dynamics.hpp"
#include "engine/contact/constraint_rows.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/run/derivative.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/contact/impact.hpp"
#include "engine/run/integrator.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/contact/lcp.hpp"
#include "engine/dynamics/motor.hpp"
#include "engine/control/controller.hpp"
#include "engine/contact/projection.hpp"
#include "engine/run/state_layout.hpp"
#include "engine/dynamics/walker_orin.hpp"

namespace elbowsim {

namespace {

std::string at_time(double t) {
  std::ostringstream s;
  s << "t = " << t << " s";
  return s.str();
}

// Mass matrix, bias and applied torques at the state in data.x.
void prepare_mechanics(const Model& model, Data& data) {
  const StateLayout s(model);
  const auto qd = data.x.segment(s.qd(), s.n);
  command(model, data, data.t, data.x.segment(s.q(), s.n), qd);
  if (s.current >= 0)
    motor_stage(model, data, qd, data.x.segment(s.current, s.n));
  else
    motor_stage(model, data, qd, data.current);
  if (model.options.dynamics == DynamicsMethod::walker_orin)
    mass_matrix_walker_orin(model, data);
  else
    mass_matrix_crba(model, data);
  bias_torques(model, data, qd);
}

std::vector<int> resting_elbows(const Data& data) {
  std::vector<int> out;
  for (std::size_t k = 0; k < data.contact.resting.size(); ++k)
    if (data.contact.resting[k]) out.push_back(int(k));
  return out;
}

}  // namespace

ContactTracker::ContactTracker(const Model& model)
    : world_(model), contacts_(model.elbows.size()), link_warned_(model.dof, false) {}

const std::vector<ElbowContact>& ContactTracker::detect(const Model& model, Data& data) {
  const StateLayout s(model);
  forward_kinematics(model, data, data.x.segment(s.q(), s.n));
  world_.elbow_contacts(model, data, contacts_);
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    data.contact.normal[k] = contacts_[k].normal;
    data.contact.surface[k] = contacts_[k].point;
  }
  return contacts_;
}

double ContactTracker::normal_speed(const Model& model, Data& data, int elbow) const {
  const StateLayout s(model);
  const Elbow& e = model.elbows[elbow];
  const Eigen::Vector3d v = point_velocity(data, e.link, e.point, data.x.segment(s.qd(), s.n));
  return data.contact.normal[elbow].dot(v);
}

bool ContactTracker::begin_step(const Model& model, Data& data, ContactLog& log) {
  ContactData& c = data.contact;
  detect(model, data);
  std::vector<int> candidates;
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    const bool touching = contacts_[k].distance <= model.contact.touch_distance &&
                          normal_speed(model, data, k) <= model.contact.separation_velocity;
    if (c.resting[k] || touching) candidates.push_back(k);
  }
  c.active = candidates;
  if (candidates.empty()) return true;

  // The active set: f >= 0, normal acceleration w >= 0, f . w = 0.
  prepare_mechanics(model, data);
  const StateLayout s(model);
  constraint_rows(model, data, data.x.segment(s.qd(), s.n));
  Eigen::MatrixXd A;
  Eigen::VectorXd b, f, w;
  contact_lcp_terms(model, data, data.actuation, A, b);
  if (model.effects.friction && (A.diagonal().array() <= 0).any()) {
    log.failure = "Painleve paradox at " + at_time(data.t) + ": with friction mu = " +
                  std::to_string(model.contact.friction) +
                  " a normal force on a resting elbow would accelerate it into the table; no "
                  "non-negative elbow force exists (lower contact.friction or change the pose)";
    return false;
  }
  // Dependent rows make the forces non-unique: start from all rows on, so the
  // minimum-norm split is kept whenever it is complementary. The Schur solve
  // above already checked the rank of M~ = Jc M^-1 Jc^T (pivots against
  // rank_tolerance), so no second factorisation here.
  const bool dependent = c.dependent;
  std::vector<bool> on(candidates.size(), true);
  if (!dependent)
    for (std::size_t r = 0; r < candidates.size(); ++r) on[r] = c.resting[candidates[r]];
  const LcpResult lcp = solve_lcp(A, b, model.contact.rank_tolerance, 1e-9, f, w, on);
  if (!lcp.solved) {
    log.failure = std::string(model.effects.friction ? "Painleve paradox" : "contact failure") +
                  " at " + at_time(data.t) +
                  ": no set of resting elbows has non-negative forces and accelerations";
    return false;
  }
  if (dependent || lcp.dependent) {
    ++log.dependent_steps;
    if (!dependent_warned_) {
      // The rank, for the message only (once per run).
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> rows(c.Jc);
      rows.setThreshold(model.contact.rank_tolerance);
      log.warnings.push_back("dependent elbow constraints at " + at_time(data.t) + ": " +
                             std::to_string(candidates.size()) + " touching elbows give rows of " +
                             "M* of rank " + std::to_string(rows.rank()) + " (threshold " +
                             std::to_string(model.contact.rank_tolerance) +
                             " relative); minimum-norm elbow forces are used");
    }
    dependent_warned_ = true;
  }
  c.active.clear();
  for (std::size_t r = 0; r < candidates.size(); ++r) {
    const int k = candidates[r];
    if (on[r]) {
      c.active.push_back(k);
      if (!c.resting[k]) log.events.push_back({data.t, k, ContactEvent::Kind::landing,
                                               std::max(0.0, -normal_speed(model, data, k)), 0, 0});
    } else if (c.resting[k]) {
      release(data, k, log);
    }
    c.resting[k] = on[r];
  }
  return true;
}

void ContactTracker::release(Data& data, int elbow, ContactLog& log) {
  data.contact.resting[elbow] = false;
  log.events.push_back({data.t, elbow, ContactEvent::Kind::release, 0, 0, 0});
}

bool ContactTracker::lands(const Model& model, int elbow, const ElbowContact& c,
                           double normal_speed) const {
  (void)model;
  return c.distance < 0 && normal_speed < 0 && elbow >= 0;
}

double ContactTracker::event_value(const Model& model, Data& data, int elbow, bool landing) {
  if (landing) return detect(model, data)[elbow].distance;
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  for (std::size_t r = 0; r < data.contact.active.size(); ++r)
    if (data.contact.active[r] == elbow) return data.contact.fn[r];
  return 0.0;
}

// Illinois (modified regula falsi) on the event function over the step,
// each evaluation integrating from the step start; returns a time just past
// the event, within model.contact.locate_tolerance.
double ContactTracker::locate(const Model& model, Data& data, double t0, double h, int elbow,
                              bool landing) {
  const long steps = data.steps;
  auto value_at = [&](double tau) {
    data.x = data.x_start;
    data.t = t0;
    data.steps = steps - 1;
    integrate_step(model, data, tau);
    return event_value(model, data, elbow, landing);
  };
  double lo = 0, hi = h, g_hi = event_value(model, data, elbow, landing);
  const double t_end = data.t;
  data.x.swap(data.x_start);
  data.t = t0;
  double g_lo = event_value(model, data, elbow, landing);
  data.x.swap(data.x_start);
  data.t = t_end;
  int side = 0;
  while (hi - lo > model.contact.locate_tolerance) {
    double tau = hi - g_hi * (hi - lo) / (g_hi - g_lo);
    if (!(tau > lo + 1e-3 * (hi - lo) && tau < hi - 1e-3 * (hi - lo))) tau = 0.5 * (lo + hi);
    const double g = value_at(tau);
    if (g < 0) {
      hi = tau, g_hi = g;
      if (side == -1) g_lo *= 0.5;
      side = -1;
    } else {
      lo = tau, g_lo = g;
      if (side == 1) g_hi *= 0.5;
      side = 1;
    }
  }
  value_at(hi);
  data.steps = steps;
  return hi;
}

bool ContactTracker::end_step(const Model& model, Data& data, double t0, ContactLog& log) {
  ContactData& c = data.contact;
  const double h = data.t - t0;
  detect(model, data);
  // Candidate events inside the step.
  int first = -1;
  bool first_is_landing = true;
  double first_time = h;
  const bool locate_events = model.contact.events == EventTiming::locate;
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    const bool landing = !c.resting[k] && lands(model, k, contacts_[k], normal_speed(model, data, k));
    bool releasing = false;
    if (locate_events && c.resting[k] && !landing) releasing = event_value(model, data, k, false) < 0;
    if (!landing && !releasing) continue;
    if (!locate_events) continue;  // step mode: handled at the boundary below
    const double tau = locate(model, data, t0, h, k, landing);
    if (tau < first_time || first < 0) first = k, first_time = tau, first_is_landing = landing;
    data.x = data.x_start;  // each search starts over from the step start
    data.t = t0;
    integrate_step(model, data, h);
    --data.steps;
  }
  if (first >= 0) {
    data.x = data.x_start;
    data.t = t0;
    integrate_step(model, data, first_time);
    --data.steps;  // the shortened step replaces the one already counted
    detect(model, data);
    if (!first_is_landing) release(data, first, log);
  }
  // Landing: every free elbow at or into the table and approaching.
  std::vector<int> landing;
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    if (c.resting[k]) continue;
    const double limit = locate_events ? model.contact.touch_distance : 0.0;
    if (contacts_[k].distance <= limit && normal_speed(model, data, k) < 0) landing.push_back(k);
  }
  if (!landing.empty()) land(model, data, landing, log);
  if (model.effects.stabilization == Stabilization::projection) {
    c.active = resting_elbows(data);
    if (!c.active.empty()) {
      const StateLayout s(model);
      EnergyTerms before, after;
      forward_kinematics(model, data, data.x.segment(s.q(), s.n));
      stored_energy(model, data, data.x.segment(s.qd(), s.n), data.x.segment(s.qd(), s.n), before);
      project_onto_constraints(model, data);
      stored_energy(model, data, data.x.segment(s.qd(), s.n), data.x.segment(s.qd(), s.n), after);
      c.projection_energy += after.mechanical() - before.mechanical();
      detect(model, data);
    }
  }
  record_drift(model, data, log);
  check_links(model, data, log);
  return true;
}

void ContactTracker::land(const Model& model, Data& data, const std::vector<int>& elbows,
                          ContactLog& log) {
  ContactData& c = data.contact;
  if (!model.effects.impacts) {
    for (int k : elbows) {
      log.events.push_back({data.t, k, ContactEvent::Kind::landing, -normal_speed(model, data, k), 0, 0});
      c.resting[k] = true;
    }
    return;
  }
  const ImpactResult r = apply_impact(model, data, elbows, resting_elbows(data));
  c.impact_loss += r.kinetic_before - r.kinetic_after;
  for (std::size_t row = 0; row < elbows.size(); ++row) {
    log.events.push_back({data.t, elbows[row], ContactEvent::Kind::landing, -r.speed_before[row],
                          r.impulse[row], r.energy_lost[row]});
    c.resting[elbows[row]] = true;
  }
}

void ContactTracker::record_drift(const Model& model, Data& data, ContactLog& log) {
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    if (!data.contact.resting[k]) continue;
    log.max_abs_C = std::max(log.max_abs_C, std::abs(contacts_[k].distance));
    log.max_abs_Cd = std::max(log.max_abs_Cd, std::abs(normal_speed(model, data, k)));
  }
}

void ContactTracker::check_links(const Model& model, Data& data, ContactLog& log) {
  world_.link_penetrations(model, data, penetrations_);
  std::vector<bool> now(link_warned_.size(), false);
  for (const LinkPenetration& p : penetrations_) {
    now[p.link] = true;
    if (link_warned_[p.link]) continue;
    std::ostringstream msg;
    msg << "link " << p.link << " passes through table box " << p.box << " at " << at_time(data.t)
        << " (depth " << p.depth << " m); only elbow spheres have contact forces";
    log.warnings.push_back(msg.str());
  }
  link_warned_ = now;
}

}  // namespace elbowsim

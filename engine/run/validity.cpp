#include "engine/run/validity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/contact/detection.hpp"
#include "engine/contact/geometry.hpp"
#include "engine/contact/pad.hpp"
#include "engine/control/controller.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/fixed_step_stability.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

void fail(Data& data, Failure f) {
  f.t = data.t;
  f.step = data.step_count;
  data.failure = f;
}

// Current and speed bounds of the motors (the state's currents with the full
// model; joint speeds with any motor).
bool within_bounds(const Model& model, Data& data) {
  if (!model.has_motor()) return true;
  const StateLayout s(model);
  const ValidityOptions& v = model.validity;
  for (int j = 0; j < model.dof; ++j) {
    const double free_speed = model.voltage_limit[j] / model.km[j];
    const double qd = std::abs(data.x[s.qd() + j]);
    if (qd > v.speed_factor * free_speed) {
      fail(data, {Failure::Kind::speed_bound, 0, 0, Failure::Part::joint, j, -1, qd,
                  v.speed_factor * free_speed});
      data.failure.diverging = true;
      return false;
    }
    if (s.current < 0) continue;
    const double stall = model.voltage_limit[j] / model.resistance[j];
    const double i = std::abs(data.x[s.current + j]);
    if (i > v.current_factor * stall) {
      fail(data, {Failure::Kind::current_bound, 0, 0, Failure::Part::joint, j, -1, i,
                  v.current_factor * stall});
      data.failure.diverging = true;
      return false;
    }
  }
  return true;
}

// Whether a ball of `reach` around `centre` can touch the box's bounds.
bool near(const Eigen::AlignedBox3d& bounds, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return (lo.array() <= bounds.max().array()).all() && (hi.array() >= bounds.min().array()).all();
}

// With contact on: every slot's distance, as the last detection measured it.
bool slots_outside_table(const Model& model, Data& data) {
  const ContactData& c = data.contact;
  // A padded elbow may press its pad down to its thickness; deeper, it bottoms out.
  auto allowed = [&](int k) {
    const Pad* pad = slot_pad(model, c, k);
    return model.contact.penetration_tolerance + (pad ? pad->thickness : 0.0);
  };
  int deepest = -1;
  for (int k = 0; k < c.slots(); ++k)
    if (-c.detected[k].distance > allowed(k) &&
        (deepest < 0 || c.detected[k].distance + allowed(k) < c.detected[deepest].distance + allowed(deepest)))
      deepest = k;
  if (deepest < 0) return true;
  const Primitive& p = c.primitive_of(deepest);
  const bool elbow = p.elbow >= 0;
  fail(data, {Failure::Kind::penetration, 0, 0, elbow ? Failure::Part::elbow : Failure::Part::link,
              elbow ? p.elbow : p.link, c.slot(deepest).box, -c.detected[deepest].distance,
              allowed(deepest)});
  return false;
}

// With contact off (no contact rows, no detection): every primitive of the
// arm (link solids, elbow spheres) against every table box, at the
// kinematics in data.
bool outside_table(const Model& model, Data& data) {
  const double tolerance = model.contact.penetration_tolerance;
  for (const Primitive& p : data.contact.geometry.primitives) {
    const Eigen::Vector3d a = data.origin[p.link] + data.rotation[p.link] * p.a;
    const Eigen::Vector3d b = data.origin[p.link] + data.rotation[p.link] * p.b;
    for (int k = 0; k < static_cast<int>(model.table.size()); ++k) {
      const TableBox& box = model.table[k];
      if (!near(box_bounds(box), a.cwiseMin(b).array() - p.radius, a.cwiseMax(b).array() + p.radius))
        continue;
      const double depth = -primitive_distance(model, data, p, box);
      if (depth <= tolerance) continue;
      const bool elbow = p.elbow >= 0;
      fail(data, {Failure::Kind::penetration, 0, 0, elbow ? Failure::Part::elbow : Failure::Part::link,
                  elbow ? p.elbow : p.link, k, depth, tolerance});
      return false;
    }
  }
  return true;
}

// Largest eigenvalue of L^-1 diag(d) L^-T (= of M^-1 diag(d)) by power
// iteration, in the scratch vectors of data.
double largest_rate(Data& data, const Eigen::VectorXd& d) {
  if (d.maxCoeff() <= 0) return 0;
  const auto L = data.llt.matrixL();
  Eigen::VectorXd& v = data.unit;
  Eigen::VectorXd& w = data.tau;
  v.setOnes();
  double lambda = 0;
  for (int k = 0; k < 100; ++k) {
    w = v;
    L.transpose().solveInPlace(w);
    w = w.cwiseProduct(d);
    L.solveInPlace(w);
    lambda = w.norm() / v.norm();
    v = w / w.norm();
  }
  return lambda;
}

}  // namespace

void check_step(const Model& model, Data& data) {
  if (!(data.x.allFinite() && data.x.cwiseAbs().maxCoeff() < 1e12)) {
    // The step that failed started at x_start: estimate the stable step there.
    data.x.swap(data.x_start);
    const double stable = stable_step_estimate(model, data);
    data.x.swap(data.x_start);
    fail(data, {Failure::Kind::diverged});
    data.failure.stable_step = stable;
    return;
  }
  if (!within_bounds(model, data)) {
    data.failure.stable_step = stable_step_estimate(model, data);
    return;
  }
  if (model.table.empty()) return;
  if (model.effects.contact) {
    slots_outside_table(model, data);
    return;
  }
  const StateLayout s(model);
  forward_kinematics(model, data, data.x.segment(s.q(), s.n));
  outside_table(model, data);
}

double energy_flow(const EnergyTerms& e) {
  return std::abs(e.electrical_in) + std::abs(e.external) + std::abs(e.normal_work) +
         std::abs(e.projection) + e.joule + e.viscous + e.friction + e.impact_loss;
}

double energy_held(const EnergyTerms& e, const EnergyTerms& initial) {
  return e.kinetic_links + e.kinetic_rotors + std::abs(e.potential - initial.potential) + e.magnetic;
}

namespace {

double energy_bound(const Model& model, const Data& data) {
  // Below 1e-10 J the residual is rounding, not a finding.
  return std::max(model.validity.energy_residual *
                      (energy_flow(data.energy) + data.validity.max_held),
                  1e-10);
}

}  // namespace

void track_energy(const Model& model, Data& data) {
  ValidityTrack& v = data.validity;
  v.max_held = std::max(v.max_held, energy_held(data.energy, data.energy_initial));
  const double residual = std::abs(balance_residual(data.energy, data.energy_initial));
  if (std::isnan(v.first_exceeded) && !(residual <= energy_bound(model, data)))
    v.first_exceeded = data.t;
}

void check_energy(const Model& model, Data& data) {
  track_energy(model, data);
  const double residual = std::abs(balance_residual(data.energy, data.energy_initial));
  const double limit = energy_bound(model, data);
  if (residual <= limit) return;
  fail(data, {Failure::Kind::energy_balance, 0, 0, Failure::Part::none, -1, -1, residual, limit,
              energy_flow(data.energy) + data.validity.max_held});
  data.failure.since = data.validity.first_exceeded;
  data.failure.stable_step = stable_step_estimate(model, data);
}

void check_planned_rest(const Model& model, const std::vector<int>& planned_resting,
                        const Recording& recording, Data& data) {
  const TrajectoryLayout& L = recording.layout;
  const std::size_t rows = recording.rows();
  if (rows < 2 || !L.has_contact()) return;
  const double span = recording.at(rows - 1, L.time()) - recording.at(0, L.time());
  for (int k : planned_resting) {
    const int column = L.elbow_resting(L.elbow(model.elbows[k].name));
    double resting = 0;
    for (std::size_t r = 0; r + 1 < rows; ++r)
      if (recording.at(r, column) >= 0.5)
        resting += recording.at(r + 1, L.time()) - recording.at(r, L.time());
    const double share = span > 0 ? resting / span : 1.0;
    if (share < model.validity.rest_share) {
      fail(data, {Failure::Kind::elbow_not_resting, 0, 0, Failure::Part::elbow, k, -1, share,
                  model.validity.rest_share});
      return;
    }
  }
}

double stable_step_estimate(const Model& model, Data& data) {
  const StateLayout s(model);
  if (!data.x.allFinite()) return 0;
  const Controller* c = data.controller.get();
  const ControllerSpec* gains = c && c->plan ? &c->spec : nullptr;
  const Eigen::VectorXd q = data.x.segment(s.q(), s.n);
  if (!is_adaptive(model.options.integrator))
    return stable_step_limit(model.options.integrator, linearise_arm(model, gains, q),
                             model.options.step);
  // Adaptive integrators choose their steps: the arm's damped and oscillatory
  // rates against a reach of 2 along the negative real axis.
  forward_kinematics(model, data, q);
  mass_matrix_crba(model, data);
  data.llt.compute(data.mass_matrix);
  if (data.llt.info() != Eigen::Success) return 0;
  Eigen::VectorXd damping = model.viscous, stiffness = Eigen::VectorXd::Zero(model.dof);
  if (model.has_motor()) {
    damping += model.km.cwiseProduct(model.km).cwiseQuotient(model.resistance);
    if (gains && gains->kind != ControllerSpec::Kind::open_loop) {
      const Eigen::VectorXd gain = model.km.cwiseQuotient(model.resistance);
      damping += gain.cwiseProduct(gains->kd);
      stiffness = gain.cwiseProduct(gains->kp);
    }
  }
  const double rate = largest_rate(data, damping) + std::sqrt(largest_rate(data, stiffness));
  return rate > 0 ? 2.0 / rate : 0;
}

}  // namespace elbowsim

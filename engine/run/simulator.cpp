#include "engine/run/simulator.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

#include "engine/run/derivative.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/run/integrator.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/recording/metrics.hpp"
#include "engine/control/plan.hpp"
#include "engine/run/state_layout.hpp"

namespace elbowsim {

namespace {

Eigen::VectorXd or_zeros(const Eigen::VectorXd& v, int n) {
  return v.size() == n ? v : Eigen::VectorXd::Zero(n);
}

void add_columns(std::vector<Column>& cols, const char* prefix, const char* unit, int n) {
  for (int j = 0; j < n; ++j) cols.push_back({prefix + std::to_string(j), unit});
}

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

// Per elbow: normal force (0 unless its row is on), signed distance, resting flag.
void append_contacts(const Model& model, Data& data, ContactTracker& tracker,
                     std::vector<double>& row) {
  const auto& contacts = tracker.detect(model, data);
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    double fn = 0;
    for (std::size_t r = 0; r < data.contact.active.size(); ++r)
      if (data.contact.active[r] == k) fn = data.contact.fn[r];
    row.insert(row.end(), {fn, contacts[k].distance, data.contact.resting[k] ? 1.0 : 0.0});
  }
}

void append(std::vector<double>& row, const Eigen::VectorXd& v) {
  row.insert(row.end(), v.data(), v.data() + v.size());
}

void record_sample(const Model& model, Data& data, ContactTracker* tracker, Recording& rec) {
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
  if (tracker) append_contacts(model, data, *tracker, row);
  const EnergyTerms& e = data.energy;
  row.insert(row.end(), {e.electrical_in, e.joule, e.viscous, e.kinetic_links, e.kinetic_rotors,
                         e.potential, e.magnetic});
  if (tracker) row.insert(row.end(), {e.friction, e.normal_work, e.impact_loss, e.projection});
  row.push_back(balance_residual(e, data.energy_initial));
}

std::string divergence_message(const Model& model, const Data& data) {
  std::ostringstream msg;
  msg << "simulation diverged at t = " << data.t << " s (step " << data.steps
      << "): the state became non-finite or exceeded 1e12; try a smaller simulation.step"
      << " (now " << model.options.step << " s) or the rk4 integrator";
  return msg.str();
}

bool state_is_sane(const Data& data) {
  return data.x.allFinite() && data.x.cwiseAbs().maxCoeff() < 1e12;
}

}  // namespace

void reset_state(const Model& model, Data& data) {
  const StateLayout s(model);
  data.t = 0;
  data.steps = 0;
  data.x.setZero();
  data.x.segment(s.q(), s.n) = or_zeros(model.initial.q, s.n);
  data.x.segment(s.qd(), s.n) = or_zeros(model.initial.qd, s.n);
  if (s.current >= 0) data.x.segment(s.current, s.n) = or_zeros(model.initial.current, s.n);
  // A tracking controller starts on its plan, with the currents that hold it.
  const Controller* controller = data.controller.get();
  if (!controller || !controller->plan || controller->spec.kind == ControllerSpec::Kind::open_loop)
    return;
  const Plan& plan = *controller->plan;
  data.x.segment(s.q(), s.n) = plan.q[0];
  data.x.segment(s.qd(), s.n) = plan.qd[0];
  if (s.current >= 0 && controller->spec.kind != ControllerSpec::Kind::pd)
    data.x.segment(s.current, s.n) =
        (plan.v_ff[0] - model.km.cwiseProduct(plan.qd[0])).cwiseQuotient(model.resistance);
}

void evaluate_outputs(const Model& model, Data& data) {
  const StateLayout s(model);
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  data.q = data.x.segment(s.q(), s.n);
  data.qd = data.x.segment(s.qd(), s.n);
  if (s.current >= 0) data.current = data.x.segment(s.current, s.n);
  // nonstiff_rates leaves the full di/dt in data.current_rate (motor_stage).
  stored_energy(model, data, data.qd, data.current, data.energy);
  data.energy.electrical_in = data.x[s.energy];
  data.energy.joule = data.x[s.energy + 1];
  data.energy.viscous = data.x[s.energy + 2];
  if (s.external >= 0) data.energy.external = data.x[s.external];
  if (!model.effects.contact) return;
  data.energy.friction = data.x[s.energy + 3];
  data.energy.normal_work = data.x[s.energy + 4];
  data.energy.impact_loss = data.contact.impact_loss;
  data.energy.projection = data.contact.projection_energy;
}

namespace {

// One step of the scene's length (shorter at the end), with the contact
// logic around it when the scene has contacts. False stops the run.
bool advance(const Model& model, Data& data, double t_end, std::optional<ContactTracker>& contacts,
             RunResult& result) {
  if (contacts && !contacts->begin_step(model, data, result.contact)) return false;
  const double t0 = data.t;
  data.x_start = data.x;
  integrate_step(model, data, std::min(model.options.step, t_end - t0));
  if (contacts && !contacts->end_step(model, data, t0, result.contact)) return false;
  if (state_is_sane(data)) return true;
  result.contact.failure = divergence_message(model, data);
  return false;
}

}  // namespace

RunResult simulate(const Model& model, const RunOptions& options) {
  return simulate(model, Experiment{}, options);
}

RunResult simulate(const Model& model, const Experiment& experiment, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const long worlds_before = model.effects.contact ? CollisionWorld::worlds_built() : 0;
  RunResult result;
  result.trajectory.columns = trajectory_columns(model, experiment.needs_plan());
  Data data(model);
  data.controller = make_controller(model, experiment);  // may throw PlanError
  std::optional<ContactTracker> contacts;
  if (model.effects.contact) contacts.emplace(model);  // no collision world otherwise
  prepare_integrator(model, data);
  reset_state(model, data);
  if (contacts) contacts->begin_step(model, data, result.contact);
  evaluate_outputs(model, data);
  data.energy_initial = data.energy;
  record_sample(model, data, contacts ? &*contacts : nullptr, result.trajectory);

  const double t_end = model.options.duration;
  const long every = std::max(1, options.record_every);
  const long expected = std::lround(t_end / model.options.step);
  const long progress_every = std::max(1L, expected / 100);
  result.completed = true;
  // Stop within a thousandth of a step of the end: t accumulates rounding.
  while (t_end - data.t > 1e-3 * model.options.step) {
    if (!advance(model, data, t_end, contacts, result)) {
      result.completed = false;
      result.failure = result.contact.failure;
      break;
    }
    const bool last = t_end - data.t <= 1e-3 * model.options.step;
    if (data.steps % every == 0 || last) {
      evaluate_outputs(model, data);
      record_sample(model, data, contacts ? &*contacts : nullptr, result.trajectory);
      result.max_abs_balance_residual =
          std::max(result.max_abs_balance_residual,
                   std::abs(balance_residual(data.energy, data.energy_initial)));
    }
    if (options.progress && data.steps % progress_every == 0)
      options.progress(data.t / t_end);
  }
  result.steps = data.steps;
  result.final_time = data.t;
  result.energy_initial = data.energy_initial;
  result.energy_final = data.energy;
  result.balance_residual = balance_residual(data.energy, data.energy_initial);
  result.warnings = result.contact.warnings;
  result.metrics = compute_metrics(model, result.trajectory);
  result.collision_worlds_built =
      model.effects.contact ? CollisionWorld::worlds_built() - worlds_before : 0;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace elbowsim

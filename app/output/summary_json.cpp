#include "app/output/summary_json.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/primitives.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/run/recorder.hpp"
#include "report/metrics.hpp"
#include "report/provenance.hpp"
#include "report/summary_keys.hpp"
#include "report/summary_units.hpp"

namespace elbowsim {

namespace key = summary_key;

namespace {

// The terms with a summary key, in the order of engine/recording/energy_terms.hpp;
// the pads' only in a scene with pads, the springs' only with springs (a scene
// without them has the summary it had before they existed).
nlohmann::ordered_json energy_json(const Model& m, const EnergyTerms& e) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const EnergyTermInfo& t : kEnergyTerms)
    if (*t.summary_key && (t.group != EnergyGroup::pads || m.has_pads()) &&
        (t.group != EnergyGroup::springs || m.has_springs()))
      j[t.summary_key] = e.*t.value;
  return j;
}

nlohmann::ordered_json model_json(const Model& m) {
  double total_mass = 0;
  for (const Link& link : m.links) total_mass += link.mass;
  return {{key::model_dof.name(), m.dof},
          {key::model_total_mass.name(), total_mass},
          {key::model_hand_link.name(), m.hand_link}};
}

// The event counts of each contact body (metrics' order: elbows, then links)
// from the run's events: a slot belongs to its primitive's elbow or link.
struct BodyEvents {
  long landings = 0, releases = 0, sticks = 0, slips = 0;
};

std::vector<BodyEvents> body_events(const Model& m, const RunResult& r) {
  const ContactGeometry geometry = contact_geometry(m);
  const Metrics& metrics = r.metrics;
  std::vector<BodyEvents> out(metrics.bodies.size());
  for (const ContactEvent& e : r.events) {
    if (e.slot < 0 || e.slot >= static_cast<int>(geometry.slots.size())) continue;
    const Primitive& p = geometry.primitives[std::size_t(geometry.slots[std::size_t(e.slot)].primitive)];
    for (std::size_t b = 0; b < metrics.bodies.size(); ++b) {
      const bool same = p.elbow >= 0 ? int(b) == p.elbow && metrics.body_links[b] < 0
                                     : metrics.body_links[b] == p.link;
      if (!same) continue;
      BodyEvents& c = out[b];
      ++(e.kind == ContactEvent::Kind::landing   ? c.landings
         : e.kind == ContactEvent::Kind::release ? c.releases
         : e.kind == ContactEvent::Kind::stick   ? c.sticks
                                                 : c.slips);
    }
  }
  return out;
}

// What the scene plans for a body: "rest" (an elbow the task keeps on the
// table, or any elbow without a task), "above" (an elbow the task holds above
// it), "none" (a link's own solid: nothing plans it to touch).
std::string planned(const Scenario& s, const Metrics& metrics, std::size_t b) {
  if (metrics.body_links[b] >= 0) return "none";
  const HandTask& task = s.experiment.task;
  const auto& kept = task.elbows;
  const bool named = std::find(kept.begin(), kept.end(), metrics.bodies[b]) != kept.end();
  if (named && task.elbow_clearance > 0) return "above";
  return "rest";
}

// Every contact body: where the scene plans it, how long it rested, its
// forces, friction work and events (one object per body, by name).
nlohmann::ordered_json bodies_json(const Scenario& s, const RunResult& r) {
  const Metrics& metrics = r.metrics;
  const std::vector<BodyEvents> events = body_events(s.model, r);
  const auto value = [&](const char* name, std::size_t b) {
    const Metric* m = metrics.find(name);
    return m ? nlohmann::ordered_json(m->values[b]) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t b = 0; b < metrics.bodies.size(); ++b) {
    nlohmann::ordered_json body;
    const int link = metrics.body_links[b];
    body[key::body_kind.name()] = link < 0 ? "elbow" : "link";
    body[key::body_link.name()] = link < 0 ? s.model.elbows[b].link : link;
    body[key::body_planned.name()] = planned(s, metrics, b);
    body[key::body_rest_fraction.name()] = value(metric::body_rest_fraction, b);
    body[key::body_force_mean.name()] = value(metric::body_force_mean, b);
    body[key::body_force_peak.name()] = value(metric::body_force_peak, b);
    if (s.model.effects.friction)
      body[key::body_friction_work.name()] = value(metric::body_friction_work, b);
    body[key::body_landings.name()] = events[b].landings;
    body[key::body_releases.name()] = events[b].releases;
    if (s.model.has_coulomb_friction()) {
      body[key::body_sticks.name()] = events[b].sticks;
      body[key::body_slips.name()] = events[b].slips;
    }
    j[metrics.bodies[b]] = body;
  }
  return j;
}

nlohmann::ordered_json contact_json(const Scenario& s, const RunResult& r) {
  const Model& m = s.model;
  long landings = 0, releases = 0, sticks = 0, slips = 0;
  for (const ContactEvent& e : r.events) {
    switch (e.kind) {
      case ContactEvent::Kind::landing: ++landings; break;
      case ContactEvent::Kind::release: ++releases; break;
      case ContactEvent::Kind::stick: ++sticks; break;
      case ContactEvent::Kind::slip: ++slips; break;
    }
  }
  nlohmann::ordered_json j = {
      {key::contact_enabled.name(), m.effects.contact},
      {key::contact_collision_worlds_built.name(), r.collision_worlds_built}};
  if (!m.effects.contact) return j;
  j[key::contact_elbows.name()] = m.elbows.size();
  j[key::contact_events.name()] = to_string(m.contact.events);
  j[key::contact_stabilization.name()] = to_string(m.effects.stabilization);
  j[key::contact_landings.name()] = landings;
  j[key::contact_releases.name()] = releases;
  if (m.has_coulomb_friction()) {
    j[key::contact_sticks.name()] = sticks;
    j[key::contact_slips.name()] = slips;
  }
  j[key::contact_max_abs_C.name()] = r.contact.max_abs_C;
  j[key::contact_max_abs_Jc_qd.name()] = r.contact.max_abs_Cd;
  j[key::contact_dependent_steps.name()] = r.contact.dependent_steps;
  j[key::contact_bodies.name()] = bodies_json(s, r);
  return j;
}

nlohmann::ordered_json settings_json(const Options& o) {
  nlohmann::ordered_json j = {{key::settings_integrator.name(), to_string(o.integrator)},
                              {key::settings_dynamics.name(), to_string(o.dynamics)},
                              {key::settings_step.name(), o.step},
                              {key::settings_duration.name(), o.duration}};
  if (is_adaptive(o.integrator)) {
    j[key::settings_rtol.name()] = o.rtol;
    j[key::settings_atol.name()] = o.atol;
    j[key::settings_max_step.name()] =
        o.max_step;  // 0: the default (step with contact, else duration / 10)
  }
  // simulation.integrator named by the scenario, or chosen by auto (and why).
  j[key::settings_integrator_choice.name()] = o.integrator_reason.empty() ? "scenario" : "auto";
  if (!o.integrator_reason.empty()) j[key::settings_integrator_reason.name()] = o.integrator_reason;
  return j;
}

}  // namespace

// "continuous", or the digital loop's settings (engine/control/digital_loop.hpp).
static nlohmann::ordered_json control_loop_json(const DigitalLoopSpec& loop) {
  if (!loop.sampled()) return "continuous";
  const SensorSpec& s = loop.sensors;
  nlohmann::ordered_json j;
  j[key::control_loop_sample_rate.name()] = 1.0 / loop.sample_period;
  j[key::control_loop_delay_samples.name()] = loop.delay;
  j[key::control_loop_pwm_bits.name()] = loop.pwm_bits;                   // 0: exact voltage
  j[key::control_loop_encoder_counts_per_rev.name()] = s.counts_per_rev;  // 0: exact angles
  j[key::control_loop_encoder_side.name()] =
      s.side == SensorSpec::EncoderSide::motor ? "motor" : "joint";
  j[key::control_loop_angle_noise.name()] = s.noise;
  j[key::control_loop_velocity_cutoff.name()] = s.velocity_cutoff;  // 0: raw backward difference
  j[key::control_loop_noise_seed.name()] = s.seed;
  return j;
}

static std::vector<double> listed_values(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

// The gains a tracking controller ran with, per joint, and the rule that
// placed them with the inertias it used (engine/control/tuning.hpp).
static nlohmann::ordered_json gains_json(const ControllerSpec& spec, const ControllerGains& g) {
  nlohmann::ordered_json j;
  j[key::controller_gains_kp.name()] = listed_values(g.kp);
  j[key::controller_gains_kd.name()] = listed_values(g.kd);
  j[key::controller_gains_ki.name()] = listed_values(g.ki);
  j[key::controller_gains_integral_held.name()] = g.integral_held;  // their ki set to 0
  if (!spec.tuning.given()) {
    j[key::controller_gains_rule.name()] = "given";
    return j;
  }
  j[key::controller_gains_rule.name()] = {
      {key::controller_gains_rule_bandwidth.name(), spec.tuning.bandwidth},
      {key::controller_gains_rule_damping.name(), spec.tuning.damping},
      {key::controller_gains_rule_integral.name(), spec.tuning.integral}};
  j[key::controller_gains_inertia.name()] = listed_values(g.inertia);
  return j;
}

nlohmann::ordered_json run_summary(const Scenario& scenario, const RunResult& result) {
  const Model& m = scenario.model;
  const double e_in = result.energy_final.electrical_in;
  nlohmann::ordered_json j;
  // first: tests/golden/golden.sh drops this block
  j[key::provenance.name()] = report::provenance_json();
  j[key::scenario.name()] = m.name;
  if (!scenario.variant.empty())
    j[key::variant.name()] = scenario.variant;  // `render` titles frames by it
  j[key::description.name()] = scenario.description;
  j[key::file.name()] = scenario.file;
  j[key::effects.name()] = m.active_effects();
  j[key::model.name()] = model_json(m);
  j[key::settings.name()] = settings_json(m.options);
  j[key::completed.name()] = result.completed;
  j[key::valid.name()] = result.valid;  // completed and every check of engine/run/validity.hpp held
  j[key::failure.name()] = result.failure;
  // by a signal (exit 128 + signal), not by the physics
  j[key::interrupted.name()] = result.interrupted;
  j[key::steps.name()] = result.steps;
  // What the integration cost: derivative evaluations (recording and events
  // included), rejected adaptive steps, Jacobians and LU factorisations.
  j[key::integrator_work.name()] = {
      {key::integrator_work_evaluations.name(), result.work.evaluations},
      {key::integrator_work_rejected_steps.name(), result.work.rejected},
      {key::integrator_work_jacobians.name(), result.work.jacobians},
      {key::integrator_work_factorisations.name(), result.work.factorisations}};
  j[key::final_time.name()] = result.final_time;
  j[key::wall_seconds.name()] = result.wall_seconds;
  j[key::energy_initial.name()] = energy_json(scenario.model, result.energy_initial);
  j[key::energy_final.name()] = energy_json(scenario.model, result.energy_final);
  j[key::balance_residual.name()] = result.balance_residual;
  j[key::max_abs_balance_residual.name()] = result.max_abs_balance_residual;
  j[key::balance_residual_relative.name()] =
      e_in != 0 ? std::abs(result.balance_residual / e_in) : 0.0;
  // the vocabulary of engine/recording/metrics.hpp
  j[key::metrics.name()] = report::metrics_json(result.metrics);
  j[key::controller.name()] = to_string(scenario.experiment.controller.kind);
  // Where the controller's model differs from the plant ([] when it knows it exactly).
  j[key::controller_model.name()] = scenario.controller_model_overrides;
  j[key::control_loop.name()] = control_loop_json(scenario.experiment.controller.loop);
  if (scenario.experiment.controller.kind != ControllerSpec::Kind::open_loop)
    j[key::controller_gains.name()] = gains_json(scenario.experiment.controller, result.gains);
  j[key::contact.name()] = contact_json(scenario, result);
  j[key::warnings.name()] = result.warnings;
  if (!result.saturation.empty())  // per motor, warnings.hpp
    j[key::saturation_share.name()] = result.saturation;
  return j;
}

std::string summary_text(const nlohmann::ordered_json& summary) {
  return report::with_units(summary).dump(2) + '\n';
}

nlohmann::ordered_json summary_shape(const Scenario& scenario, bool step_check) {
  const Model& model = scenario.model;
  RunResult placeholder;
  placeholder.trajectory =
      Recording(trajectory_layout(model, scenario.experiment.needs_plan()));
  const std::size_t columns = placeholder.trajectory.columns().size();
  placeholder.trajectory.values.assign(2 * columns, 0.0);
  placeholder.trajectory.values[columns] = model.options.duration;  // row 1's time
  // A link without a solid has no finite distance: it is no contact body.
  const Eigen::VectorXd zeros = Eigen::VectorXd::Zero(model.dof);
  placeholder.gains = {zeros, zeros, zeros,
                       scenario.experiment.controller.tuning.given() ? zeros : Eigen::VectorXd(), {}};
  const TrajectoryLayout& layout = placeholder.trajectory.layout;
  if (layout.has_contact())
    for (int j = 0; j < model.dof; ++j)
      if (model.links[std::size_t(j)].collision.kind == LinkCollision::Kind::none)
        for (std::size_t row : {std::size_t(0), columns})
          placeholder.trajectory.values[row + std::size_t(layout.link_distance(j))] = INFINITY;
  placeholder.metrics = compute_metrics(placeholder.trajectory);
  if (model.has_motor()) placeholder.saturation.assign(static_cast<std::size_t>(model.dof), 0.0);
  nlohmann::ordered_json shape = run_summary(scenario, placeholder);
  if (step_check) shape[key::step_check.name()] = nullptr;
  return shape;
}

}  // namespace elbowsim

#include "app/output/summary_json.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/primitives.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/run/recorder.hpp"
#include "report/metrics.hpp"
#include "report/provenance.hpp"
#include "report/summary_units.hpp"

namespace elbowsim {

namespace {

// The terms with a summary key, in the order of engine/recording/energy_terms.hpp.
nlohmann::ordered_json energy_json(const EnergyTerms& e) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const EnergyTermInfo& t : kEnergyTerms)
    if (*t.summary_key) j[t.summary_key] = e.*t.value;
  return j;
}

nlohmann::ordered_json model_json(const Model& m) {
  double total_mass = 0;
  for (const Link& link : m.links) total_mass += link.mass;
  return {{"dof", m.dof}, {"total_mass", total_mass}, {"hand_link", m.hand_link}};
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
    body["kind"] = link < 0 ? "elbow" : "link";
    body["link"] = link < 0 ? s.model.elbows[b].link : link;
    body["planned"] = planned(s, metrics, b);
    body["rest_fraction"] = value("body_rest_fraction", b);
    body["force_mean"] = value("body_force_mean", b);
    body["force_peak"] = value("body_force_peak", b);
    if (s.model.effects.friction) body["friction_work"] = value("body_friction_work", b);
    body["landings"] = events[b].landings;
    body["releases"] = events[b].releases;
    if (s.model.has_coulomb_friction()) {
      body["sticks"] = events[b].sticks;
      body["slips"] = events[b].slips;
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
  nlohmann::ordered_json j = {{"enabled", m.effects.contact},
                              {"collision_worlds_built", r.collision_worlds_built}};
  if (!m.effects.contact) return j;
  j["elbows"] = m.elbows.size();
  j["events"] = to_string(m.contact.events);
  j["stabilization"] = to_string(m.effects.stabilization);
  j["landings"] = landings;
  j["releases"] = releases;
  if (m.has_coulomb_friction()) {
    j["sticks"] = sticks;
    j["slips"] = slips;
  }
  j["max_abs_C"] = r.contact.max_abs_C;
  j["max_abs_Jc_qd"] = r.contact.max_abs_Cd;
  j["dependent_steps"] = r.contact.dependent_steps;
  j["bodies"] = bodies_json(s, r);
  return j;
}

nlohmann::ordered_json settings_json(const Options& o) {
  nlohmann::ordered_json j = {{"integrator", to_string(o.integrator)}, {"dynamics", to_string(o.dynamics)},
                              {"step", o.step}, {"duration", o.duration}};
  if (is_adaptive(o.integrator)) {
    j["rtol"] = o.rtol;
    j["atol"] = o.atol;
    j["max_step"] = o.max_step;  // 0: the default (step with contact, else duration / 10)
  }
  // simulation.integrator named by the scenario, or chosen by auto (and why).
  j["integrator_choice"] = o.integrator_reason.empty() ? "scenario" : "auto";
  if (!o.integrator_reason.empty()) j["integrator_reason"] = o.integrator_reason;
  return j;
}

}  // namespace

// "continuous", or the digital loop's settings (engine/control/digital_loop.hpp).
static nlohmann::ordered_json control_loop_json(const DigitalLoopSpec& loop) {
  if (!loop.sampled()) return "continuous";
  const SensorSpec& s = loop.sensors;
  nlohmann::ordered_json j;
  j["sample_rate"] = 1.0 / loop.sample_period;
  j["delay_samples"] = loop.delay;
  j["pwm_bits"] = loop.pwm_bits;  // 0: exact voltage
  j["encoder_counts_per_rev"] = s.counts_per_rev;  // 0: exact angles
  j["encoder_side"] = s.side == SensorSpec::EncoderSide::motor ? "motor" : "joint";
  j["angle_noise"] = s.noise;
  j["velocity_cutoff"] = s.velocity_cutoff;  // 0: raw backward difference
  j["noise_seed"] = s.seed;
  return j;
}

nlohmann::ordered_json run_summary(const Scenario& scenario, const RunResult& result) {
  const Model& m = scenario.model;
  const double e_in = result.energy_final.electrical_in;
  nlohmann::ordered_json j;
  j["provenance"] = report::provenance_json();  // first: tests/golden/golden.sh drops this block
  j["scenario"] = m.name;
  if (!scenario.variant.empty()) j["variant"] = scenario.variant;  // `render` titles frames by it
  j["description"] = scenario.description;
  j["file"] = scenario.file;
  j["effects"] = m.active_effects();
  j["model"] = model_json(m);
  j["settings"] = settings_json(m.options);
  j["completed"] = result.completed;
  j["valid"] = result.valid;  // completed and every check of engine/run/validity.hpp held
  j["failure"] = result.failure;
  j["interrupted"] = result.interrupted;  // by a signal (exit 128 + signal), not by the physics
  j["steps"] = result.steps;
  // What the integration cost: derivative evaluations (recording and events
  // included), rejected adaptive steps, Jacobians and LU factorisations.
  j["integrator_work"] = {{"evaluations", result.work.evaluations},
                          {"rejected_steps", result.work.rejected},
                          {"jacobians", result.work.jacobians},
                          {"factorisations", result.work.factorisations}};
  j["final_time"] = result.final_time;
  j["wall_seconds"] = result.wall_seconds;
  j["energy_initial"] = energy_json(result.energy_initial);
  j["energy_final"] = energy_json(result.energy_final);
  j["balance_residual"] = result.balance_residual;
  j["max_abs_balance_residual"] = result.max_abs_balance_residual;
  j["balance_residual_relative"] = e_in != 0 ? std::abs(result.balance_residual / e_in) : 0.0;
  j["metrics"] = report::metrics_json(result.metrics);  // the vocabulary of engine/recording/metrics.hpp
  j["controller"] = to_string(scenario.experiment.controller.kind);
  // Where the controller's model differs from the plant ([] when it knows it exactly).
  j["controller_model"] = scenario.controller_model_overrides;
  j["control_loop"] = control_loop_json(scenario.experiment.controller.loop);
  j["contact"] = contact_json(scenario, result);
  j["warnings"] = result.warnings;
  if (!result.saturation.empty()) j["saturation_share"] = result.saturation;  // per motor, warnings.hpp
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
  const TrajectoryLayout& layout = placeholder.trajectory.layout;
  if (layout.has_contact())
    for (int j = 0; j < model.dof; ++j)
      if (model.links[std::size_t(j)].collision.kind == LinkCollision::Kind::none)
        for (std::size_t row : {std::size_t(0), columns})
          placeholder.trajectory.values[row + std::size_t(layout.link_distance(j))] = INFINITY;
  placeholder.metrics = compute_metrics(placeholder.trajectory);
  if (model.has_motor()) placeholder.saturation.assign(static_cast<std::size_t>(model.dof), 0.0);
  nlohmann::ordered_json shape = run_summary(scenario, placeholder);
  if (step_check) shape["step_check"] = nullptr;
  return shape;
}

}  // namespace elbowsim

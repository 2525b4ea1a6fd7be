#include "app/output/summary_json.hpp"

#include "engine/dynamics/energy.hpp"
#include "engine/run/recorder.hpp"
#include "report/metrics.hpp"

namespace elbowsim {

namespace {

nlohmann::ordered_json energy_json(const EnergyTerms& e) {
  return {{"electrical_in", e.electrical_in}, {"joule", e.joule},
          {"viscous", e.viscous},             {"kinetic_links", e.kinetic_links},
          {"kinetic_rotors", e.kinetic_rotors}, {"potential", e.potential},
          {"magnetic", e.magnetic}, {"friction", e.friction},
          {"normal_work", e.normal_work}, {"impact_loss", e.impact_loss},
          {"projection", e.projection}, {"drawn", e.drawn}, {"regenerated", e.regenerated},
          {"joint_friction", e.joint_friction}, {"gear_loss", e.gear_loss}};
}

nlohmann::ordered_json model_json(const Model& m) {
  double total_mass = 0;
  for (const Link& link : m.links) total_mass += link.mass;
  return {{"dof", m.dof}, {"total_mass", total_mass}, {"hand_link", m.hand_link}};
}

nlohmann::ordered_json contact_json(const Model& m, const RunResult& r) {
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
  j["contact"] = contact_json(m, result);
  j["warnings"] = result.warnings;
  if (!result.saturation.empty()) j["saturation_share"] = result.saturation;  // per motor, warnings.hpp
  return j;
}

nlohmann::ordered_json summary_shape(const Scenario& scenario, bool step_check) {
  const Model& model = scenario.model;
  RunResult placeholder;
  placeholder.trajectory =
      Recording(trajectory_layout(model, scenario.experiment.needs_plan()));
  const std::size_t columns = placeholder.trajectory.columns().size();
  placeholder.trajectory.values.assign(2 * columns, 0.0);
  placeholder.trajectory.values[columns] = model.options.duration;  // row 1's time
  placeholder.metrics = compute_metrics(placeholder.trajectory);
  if (model.has_motor()) placeholder.saturation.assign(static_cast<std::size_t>(model.dof), 0.0);
  nlohmann::ordered_json shape = run_summary(scenario, placeholder);
  if (step_check) shape["step_check"] = nullptr;
  return shape;
}

}  // namespace elbowsim

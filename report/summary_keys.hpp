// summary.json's schema: every key of the file once, by its dotted path, with
// the unit of the number it holds (ELBOWSIM_SUMMARY_KEYS below, an X-macro as
// engine/recording/metrics.hpp lists the metrics). The writers
// (app/output/summary_json.cpp, app/commands/step_check.cpp, app/commands/run.cpp)
// and the readers (report/, app/) name keys by these constants; the units
// map of the file (report/summary_units.hpp) and the reports' labels come
// from the same rows. docs/outputs.md describes each key.
//
// Paths are dotted; "*" stands for any one key or list index (a contact
// body's name, a metric's name). Units are SI symbols ("m", "J", "N", "s",
// "A", "W", "kg", "Hz", "rad", "m/s"; the gains' "V/rad", "V s/rad", "V/(rad s)",
// "kg m^2"); "1" is a pure number (a count, an
// index, a ratio or a share); "state" is the integrated state's own units
// (rad, rad/s, A, J: an absolute tolerance); "metric" is the unit of the
// metric named after "metrics." (engine/recording/metrics.hpp); "" is not a
// number (text, a flag, an object, a list of names). A list's elements are
// "<list>.*" (saturation_share.*: per motor).
#pragma once

#include <string>
#include <string_view>

#include "engine/recording/energy_terms.hpp"
#include "engine/recording/metrics.hpp"

// X(name, path, unit)
#define ELBOWSIM_SUMMARY_KEYS(X)                                                     \
  X(provenance, "provenance", "")                                                    \
  X(units, "units", "")                                                              \
  X(scenario, "scenario", "")                                                        \
  X(variant, "variant", "")                                                          \
  X(description, "description", "")                                                  \
  X(file, "file", "")                                                                \
  X(effects, "effects", "")                                                          \
  X(model, "model", "")                                                              \
  X(model_dof, "model.dof", "1")                                                     \
  X(model_total_mass, "model.total_mass", "kg")                                      \
  X(model_hand_link, "model.hand_link", "1")                                         \
  X(settings, "settings", "")                                                        \
  X(settings_integrator, "settings.integrator", "")                                  \
  X(settings_dynamics, "settings.dynamics", "")                                      \
  X(settings_step, "settings.step", "s")                                             \
  X(settings_duration, "settings.duration", "s")                                     \
  X(settings_rtol, "settings.rtol", "1")                                             \
  X(settings_atol, "settings.atol", "state")                                         \
  X(settings_max_step, "settings.max_step", "s")                                     \
  X(settings_integrator_choice, "settings.integrator_choice", "")                    \
  X(settings_integrator_reason, "settings.integrator_reason", "")                    \
  X(completed, "completed", "")                                                      \
  X(valid, "valid", "")                                                              \
  X(failure, "failure", "")                                                          \
  X(interrupted, "interrupted", "")                                                  \
  X(interrupted_stage, "interrupted_stage", "")                                      \
  X(steps, "steps", "1")                                                             \
  X(integrator_work, "integrator_work", "")                                          \
  X(integrator_work_evaluations, "integrator_work.evaluations", "1")                 \
  X(integrator_work_rejected_steps, "integrator_work.rejected_steps", "1")           \
  X(integrator_work_jacobians, "integrator_work.jacobians", "1")                     \
  X(integrator_work_factorisations, "integrator_work.factorisations", "1")           \
  X(final_time, "final_time", "s")                                                   \
  X(wall_seconds, "wall_seconds", "s")                                               \
  X(energy_initial, "energy_initial", "")                                            \
  X(energy_initial_term, "energy_initial.*", "J")                                    \
  X(energy_final, "energy_final", "")                                                \
  X(energy_final_term, "energy_final.*", "J")                                        \
  X(balance_residual, "balance_residual", "J")                                       \
  X(max_abs_balance_residual, "max_abs_balance_residual", "J")                       \
  X(balance_residual_relative, "balance_residual_relative", "1")                     \
  X(metrics, "metrics", "")                                                          \
  X(metric_value, "metrics.*", "metric")                                             \
  X(metric_entry, "metrics.*.*", "metric")                                           \
  X(controller, "controller", "")                                                    \
  X(controller_model, "controller_model", "")                                        \
  X(control_loop, "control_loop", "")                                                \
  X(control_loop_sample_rate, "control_loop.sample_rate", "Hz")                      \
  X(control_loop_delay_samples, "control_loop.delay_samples", "1")                   \
  X(control_loop_pwm_bits, "control_loop.pwm_bits", "1")                             \
  X(control_loop_encoder_counts_per_rev, "control_loop.encoder_counts_per_rev", "1") \
  X(control_loop_encoder_side, "control_loop.encoder_side", "")                      \
  X(control_loop_angle_noise, "control_loop.angle_noise", "rad")                     \
  X(control_loop_velocity_cutoff, "control_loop.velocity_cutoff", "Hz")              \
  X(control_loop_noise_seed, "control_loop.noise_seed", "1")                         \
  X(controller_gains, "controller_gains", "")                                        \
  X(controller_gains_kp, "controller_gains.kp", "")                                  \
  X(controller_gains_kp_joint, "controller_gains.kp.*", "V/rad")                     \
  X(controller_gains_kd, "controller_gains.kd", "")                                  \
  X(controller_gains_kd_joint, "controller_gains.kd.*", "V s/rad")                   \
  X(controller_gains_ki, "controller_gains.ki", "")                                  \
  X(controller_gains_ki_joint, "controller_gains.ki.*", "V/(rad s)")                 \
  X(controller_gains_integral_held, "controller_gains.integral_held", "")            \
  X(controller_gains_integral_held_joint, "controller_gains.integral_held.*", "1")    \
  X(controller_gains_rule, "controller_gains.rule", "")                              \
  X(controller_gains_rule_bandwidth, "controller_gains.rule.bandwidth", "Hz")        \
  X(controller_gains_rule_damping, "controller_gains.rule.damping", "1")             \
  X(controller_gains_rule_integral, "controller_gains.rule.integral", "1")           \
  X(controller_gains_inertia, "controller_gains.inertia", "")                        \
  X(controller_gains_inertia_joint, "controller_gains.inertia.*", "kg m^2")          \
  X(contact, "contact", "")                                                          \
  X(contact_enabled, "contact.enabled", "")                                          \
  X(contact_collision_worlds_built, "contact.collision_worlds_built", "1")           \
  X(contact_elbows, "contact.elbows", "1")                                           \
  X(contact_events, "contact.events", "")                                            \
  X(contact_stabilization, "contact.stabilization", "")                              \
  X(contact_landings, "contact.landings", "1")                                       \
  X(contact_releases, "contact.releases", "1")                                       \
  X(contact_sticks, "contact.sticks", "1")                                           \
  X(contact_slips, "contact.slips", "1")                                             \
  X(contact_max_abs_C, "contact.max_abs_C", "m")                                     \
  X(contact_max_abs_Jc_qd, "contact.max_abs_Jc_qd", "m/s")                           \
  X(contact_dependent_steps, "contact.dependent_steps", "1")                         \
  X(contact_bodies, "contact.bodies", "")                                            \
  X(body_kind, "contact.bodies.*.kind", "")                                          \
  X(body_link, "contact.bodies.*.link", "1")                                         \
  X(body_planned, "contact.bodies.*.planned", "")                                    \
  X(body_rest_fraction, "contact.bodies.*.rest_fraction", "1")                       \
  X(body_force_mean, "contact.bodies.*.force_mean", "N")                             \
  X(body_force_peak, "contact.bodies.*.force_peak", "N")                             \
  X(body_friction_work, "contact.bodies.*.friction_work", "J")                       \
  X(body_landings, "contact.bodies.*.landings", "1")                                 \
  X(body_releases, "contact.bodies.*.releases", "1")                                 \
  X(body_sticks, "contact.bodies.*.sticks", "1")                                     \
  X(body_slips, "contact.bodies.*.slips", "1")                                       \
  X(warnings, "warnings", "")                                                        \
  X(saturation_share, "saturation_share", "")                                        \
  X(saturation_share_motor, "saturation_share.*", "1")                               \
  X(step_check, "step_check", "")                                                    \
  X(step_check_error, "step_check.error", "")                                        \
  X(step_check_refinement, "step_check.refinement", "")                              \
  X(step_check_step, "step_check.step", "s")                                         \
  X(step_check_half_step, "step_check.half_step", "s")                               \
  X(step_check_valid_at_half_step, "step_check.valid_at_half_step", "")              \
  X(step_check_failure_at_half_step, "step_check.failure_at_half_step", "")          \
  X(step_check_metrics, "step_check.metrics", "")                                    \
  X(checked_unit, "step_check.metrics.*.unit", "")                                   \
  X(checked_value, "step_check.metrics.*.value", "metric")                           \
  X(checked_at_half_step, "step_check.metrics.*.at_half_step", "metric")             \
  X(checked_relative_change, "step_check.metrics.*.relative_change", "1")            \
  X(checked_floor, "step_check.metrics.*.floor", "metric")                           \
  X(checked_below_floor, "step_check.metrics.*.below_floor", "")                     \
  X(step_check_below_floor, "step_check.below_floor", "")

namespace elbowsim {

// One key of summary.json.
struct SummaryKey {
  std::string_view path;  // "contact.max_abs_C": as --expect, the units map and the docs name it
  std::string_view unit;  // as above
  // The key in its object ("max_abs_C"): what a writer or reader of that object indexes by.
  constexpr std::string_view name() const { return path.substr(path.rfind('.') + 1); }
  // The path as a JSON pointer ("/contact/max_abs_C").
  std::string pointer() const;
};

namespace summary_key {
inline constexpr std::string_view kMetricUnit = "metric";  // the named metric's own unit

#define ELBOWSIM_SUMMARY_KEY(name, path, unit) inline constexpr SummaryKey name{path, unit};
ELBOWSIM_SUMMARY_KEYS(ELBOWSIM_SUMMARY_KEY)
#undef ELBOWSIM_SUMMARY_KEY

inline constexpr SummaryKey kAll[] = {
#define ELBOWSIM_SUMMARY_KEY(name, path, unit) name,
    ELBOWSIM_SUMMARY_KEYS(ELBOWSIM_SUMMARY_KEY)
#undef ELBOWSIM_SUMMARY_KEY
};

// A dotted path as a JSON pointer: "contact.max_abs_C" is "/contact/max_abs_C".
inline std::string json_pointer(std::string_view path) {
  std::string p(1, '/');
  p.append(path);
  for (char& c : p)
    if (c == '.') c = '/';
  return p;
}

// The path of an energy term at the run's end: "energy_final.joule" (the term's
// summary key, engine/recording/energy_terms.hpp).
inline std::string energy_final_path(Energy term) {
  return std::string(energy_final.path) + "." + energy_term(term).summary_key;
}

// The path of a metric in summary.json: "metrics.hand_error_rms".
inline std::string metric_path(std::string_view metric_name) {
  return std::string(metrics.path) + "." + std::string(metric_name);
}

// The metric a path of summary.json names ("metrics.current_rms.2": "current_rms"),
// "" for a path outside "metrics".
inline std::string_view metric_of(std::string_view path) {
  const std::string_view prefix = metrics.path;
  if (!(path.size() > prefix.size() && path.starts_with(prefix) && path[prefix.size()] == '.'))
    return {};
  const std::string_view rest = path.substr(prefix.size() + 1);
  return rest.substr(0, rest.find('.'));
}

// The path of a metric's step check: "step_check.metrics.joule".
inline std::string checked_metric_path(std::string_view metric_name) {
  return std::string(step_check_metrics.path) + "." + std::string(metric_name);
}
}  // namespace summary_key

inline std::string SummaryKey::pointer() const { return summary_key::json_pointer(path); }

}  // namespace elbowsim

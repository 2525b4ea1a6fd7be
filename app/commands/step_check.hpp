// --check-step: the run again at half its step, and how much every headline
// metric moved. A metric that changes by a large fraction is integration
// error, not a result (README: "What the experiment says").
#pragma once

#include <nlohmann/json.hpp>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

// The scenario as run (its resolved YAML) at half its step, recording at the
// same instants (output.every doubled), so RMS metrics average the same
// samples. Throws ScenarioError.
Scenario at_half_step(const Scenario& scenario);

// Reruns `scenario` (from its resolved YAML) at half the step, recording at
// the same instants, and returns {step, half_step, valid_at_half_step,
// metrics: {name: {unit, value, at_half_step, relative_change}}} for every
// one-value metric of `result`. Throws ScenarioError (the halved step is not
// a valid scenario) or PlanError. SIGINT or SIGTERM (interrupt.hpp) stops
// the rerun: its numbers are then those of a cut run, not to be used.
nlohmann::ordered_json check_step(const Scenario& scenario, const RunResult& result);

}  // namespace elbowsim

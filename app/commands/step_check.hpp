// --check-step: the run again at half its step, and how much every headline
// metric moved. A metric that changes by a large fraction is integration
// error, not a result (README: "What the experiment says").
#pragma once

#include <nlohmann/json.hpp>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

// Reruns `scenario` (from its resolved YAML) at half the step, recording at
// the same instants, and returns {step, half_step, valid_at_half_step,
// metrics: {name: {unit, value, at_half_step, relative_change}}} for every
// one-value metric of `result`. Throws ScenarioError (the halved step is not
// a valid scenario) or PlanError.
nlohmann::ordered_json check_step(const Scenario& scenario, const RunResult& result);

}  // namespace elbowsim

// summary.json: what ran (scenario, effects, settings), how it went (steps,
// wall time, failure, warnings) and the final energy account.
#pragma once

#include <nlohmann/json.hpp>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

nlohmann::ordered_json run_summary(const Scenario& scenario, const RunResult& result);

// What a run of `scenario` would write as summary.json, with placeholder
// values (a two-row recording of zeros): its keys, for checking --expect
// paths before simulating. With `step_check`, a null step_check (anything
// under it is accepted).
nlohmann::ordered_json summary_shape(const Scenario& scenario, bool step_check);

}  // namespace elbowsim

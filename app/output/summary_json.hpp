// summary.json: what ran (scenario, effects, settings), how it went (steps,
// wall time, failure, warnings) and the final energy account.
#pragma once

#include <nlohmann/json.hpp>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

nlohmann::ordered_json run_summary(const Scenario& scenario, const RunResult& result);

}  // namespace elbowsim

// summary.json: what ran (scenario, effects, settings), how it went (steps,
// wall time, failure, warnings) and the final energy account.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

nlohmann::ordered_json run_summary(const Scenario& scenario, const RunResult& result);

// summary.json's text: `summary` (with whatever the commands added, such as step_check)
// and, second, its "units" (report/summary_units.hpp).
std::string summary_text(const nlohmann::ordered_json& summary);

// What a run of `scenario` would write as summary.json, with placeholder
// values (a two-row recording of zeros): its keys, for checking --expect
// paths before simulating. With `step_check`, a null step_check (anything
// under it is accepted).
nlohmann::ordered_json summary_shape(const Scenario& scenario, bool step_check);

}  // namespace elbowsim

// The step check: the run again with its integration refined, and how much
// every headline metric moved. A metric that changes by a large fraction is
// integration error, not a result. It runs with every `run` unless switched
// off (--no-check-step): each number a run reports says how much of it is the
// integrator's.
//
// Refined means half the step for a fixed-step integrator (recording at the
// same instants, the plan sampled as before) and rtol, atol / 10 for an
// adaptive one (its step follows its tolerance, not simulation.step). The
// change is the floor below which a metric measures the integrator: a metric
// within kFloorFactor of it is "below the integration floor", never a result.
#pragma once

#include <nlohmann/json.hpp>

#include "app/scenario/scenario.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

// A metric smaller than this many times its change under refinement measures
// the integrator (10: the change is then more than a tenth of the value).
constexpr double kFloorFactor = 10;

// The scenario as run (its resolved YAML) with its integration refined (above),
// the integrator pinned to the one it ran with (an automatic choice could
// change with the step). Throws ScenarioError.
Scenario at_half_step(const Scenario& scenario);

// What the refinement is, in words: "half the step (0.5 ms)" or "rtol and atol / 10".
std::string refinement_text(const Scenario& scenario);

// Reruns `scenario` refined and returns {refinement, step, half_step (fixed
// steps), valid_at_half_step, metrics: {name: {unit, value, at_half_step,
// relative_change, floor, below_floor}}, below_floor: [names]} for every
// one-value metric of `result`; floor = |value - at_half_step|, below_floor:
// |value| < kFloorFactor floor. Throws ScenarioError or PlanError. SIGINT or
// SIGTERM (interrupt.hpp) stops the rerun: its numbers are then those of a
// cut run, not to be used.
nlohmann::ordered_json check_step(const Scenario& scenario, const RunResult& result);

}  // namespace elbowsim

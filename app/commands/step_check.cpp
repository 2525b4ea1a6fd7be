#include "app/commands/step_check.hpp"

#include <cmath>

#include "app/commands/interrupt.hpp"
#include "app/study/draws.hpp"
#include "engine/recording/number_text.hpp"
#include "engine/run/simulator.hpp"
#include "report/summary_keys.hpp"

namespace elbowsim {

namespace key = summary_key;

Scenario at_half_step(const Scenario& scenario) {
  const Options& o = scenario.model.options;
  std::vector<std::string> overrides{"simulation.integrator=" + std::string(to_string(o.integrator))};
  if (is_adaptive(o.integrator)) {
    overrides.push_back("simulation.rtol=" + round_trip(o.rtol / 10));
    overrides.push_back("simulation.atol=" + round_trip(o.atol / 10));
  } else {
    overrides.push_back("simulation.step=" + round_trip(o.step / 2));
    overrides.push_back("output.every=" + std::to_string(2 * scenario.output.every));
  }
  // The plan stays sampled as the scenario's: only the integration changes.
  if (scenario.experiment.needs_plan() && scenario.experiment.task.plan_step <= 0)
    overrides.push_back("task.plan_step=" + round_trip(o.step));
  return load_scenario_text(scenario.resolved_yaml, scenario.file, overrides);
}

std::string refinement_text(const Scenario& scenario) {
  const Options& o = scenario.model.options;
  if (is_adaptive(o.integrator)) return "rtol and atol / 10";
  return "half the step (" + significant(o.step / 2) + " s)";
}

nlohmann::ordered_json check_step(const Scenario& scenario, const RunResult& result) {
  const double h = scenario.model.options.step;
  const Scenario halved = at_half_step(scenario);
  // A signal stops it as it stops the run (the caller then drops the result).
  const RunResult half = simulate(halved.model, halved.experiment,
                                  RunOptions{halved.output.every, {}, &interrupt_flag()});
  nlohmann::ordered_json j;
  j[key::step_check_refinement.name()] = refinement_text(scenario);
  j[key::step_check_step.name()] = h;
  if (!is_adaptive(scenario.model.options.integrator)) j[key::step_check_half_step.name()] = h / 2;
  j[key::step_check_valid_at_half_step.name()] = half.valid;
  if (!half.valid) j[key::step_check_failure_at_half_step.name()] = half.failure;
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  nlohmann::ordered_json below = nlohmann::ordered_json::array();
  for (const Metric& m : result.metrics.list) {
    if (m.shape != Metric::Shape::one) continue;
    const Metric* other = half.metrics.find(m.name);
    if (!other) continue;
    const double a = m.values.front(), b = other->values.front();
    const double scale = std::max(std::abs(a), std::abs(b));
    const double floor = std::abs(a - b);
    const bool below_floor = half.valid && std::abs(a) < kFloorFactor * floor;
    metrics[m.name] = {{key::checked_unit.name(), m.unit},
                       {key::checked_value.name(), a},
                       {key::checked_at_half_step.name(), b},
                       {key::checked_relative_change.name(), scale > 0 ? floor / scale : 0.0},
                       {key::checked_floor.name(), floor},
                       {key::checked_below_floor.name(), below_floor}};
    if (below_floor) below.push_back(m.name);
  }
  j[key::step_check_metrics.name()] = metrics;
  j[key::step_check_below_floor.name()] = below;
  return j;
}

}  // namespace elbowsim

#include "app/commands/step_check.hpp"

#include <cmath>

#include "app/study/draws.hpp"
#include "engine/run/simulator.hpp"

namespace elbowsim {

Scenario at_half_step(const Scenario& scenario) {
  std::vector<std::string> overrides{"simulation.step=" + study::exact(scenario.model.options.step / 2),
                                     "output.every=" + std::to_string(2 * scenario.output.every)};
  // The plan stays sampled as the scenario's: only the integration changes.
  if (scenario.experiment.needs_plan() && scenario.experiment.task.plan_step <= 0)
    overrides.push_back("task.plan_step=" + study::exact(scenario.model.options.step));
  // The integrator auto chose at the scenario's step, not the one it would choose at half of it.
  if (!scenario.model.options.integrator_reason.empty())
    overrides.push_back(std::string("simulation.integrator=") +
                        to_string(scenario.model.options.integrator));
  return load_scenario_text(scenario.resolved_yaml, scenario.file, overrides);
}

nlohmann::ordered_json check_step(const Scenario& scenario, const RunResult& result) {
  const double h = scenario.model.options.step;
  const Scenario halved = at_half_step(scenario);
  const RunResult half = simulate(halved.model, halved.experiment, RunOptions{halved.output.every, {}});
  nlohmann::ordered_json j;
  j["step"] = h;
  j["half_step"] = h / 2;
  j["valid_at_half_step"] = half.valid;
  if (!half.valid) j["failure_at_half_step"] = half.failure;
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const Metric& m : result.metrics.list) {
    if (m.shape != Metric::Shape::one) continue;
    const Metric* other = half.metrics.find(m.name);
    if (!other) continue;
    const double a = m.values.front(), b = other->values.front();
    const double scale = std::max(std::abs(a), std::abs(b));
    metrics[m.name] = {{"unit", m.unit},
                       {"value", a},
                       {"at_half_step", b},
                       {"relative_change", scale > 0 ? std::abs(a - b) / scale : 0.0}};
  }
  j["metrics"] = metrics;
  return j;
}

}  // namespace elbowsim

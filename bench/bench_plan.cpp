// The controller's plan (constrained inverse kinematics at every sample, then
// the feed-forward) on shipped scenes: the start-up cost every run of a task
// pays before its first step.
#include <benchmark/benchmark.h>

#include <string>

#include "app/scenario/scenario.hpp"
#include "engine/control/plan.hpp"

using namespace elbowsim;

namespace {

void plan_cost(benchmark::State& state, const std::string& file, const std::string& variant) {
  const std::string path = std::string(ELBOWSIM_SOURCE_DIR) + "/scenarios/" + file;
  const Scenario s = variant.empty() ? load_scenario(path) : load_scenario_variant(path, variant);
  for (auto _ : state) benchmark::DoNotOptimize(make_plan(s.model, s.experiment).get());
  state.counters["samples"] = double(make_plan(s.model, s.experiment)->q.size());
}

}  // namespace

BENCHMARK_CAPTURE(plan_cost, experiment_elbow_on, "elbow_experiment.yaml", "elbow_on")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plan_cost, experiment_elbow_off, "elbow_experiment.yaml", "elbow_off")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plan_cost, spatial_two_elbows, "hard/spatial_two_elbows.yaml", "")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plan_cost, long_chain, "hard/long_chain.yaml", "")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

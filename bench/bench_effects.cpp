// Cost of one RK4 step on the same 7-joint robot for growing effect sets:
// a scene pays only for the effects it switches on.
#include <benchmark/benchmark.h>

#include "engine/run/integrator.hpp"
#include "engine/run/simulator.hpp"
#include "engine/run/step.hpp"
#include "support/models.hpp"

using namespace elbowsim;

namespace {

Model with_effects(bool gravity, bool damping, MotorModel motor, bool rotor) {
  Model m = testing::random_chain(7, 77);
  m.effects = {gravity, damping, motor, rotor};
  m.options = {1.0, 1e-3, IntegratorKind::rk4, DynamicsMethod::crba};
  finalize(m);
  return m;
}

void step_cost(benchmark::State& state, const Model& model) {
  Data data(model);
  prepare_integrator(model, data);
  reset_state(model, data);
  for (auto _ : state) {
    integrate_step(model, data);
    if (data.step_count % 1000 == 0) reset_state(model, data);  // stay near the start
    benchmark::DoNotOptimize(data.x.data());
  }
}

}  // namespace

BENCHMARK_CAPTURE(step_cost, bare, with_effects(false, false, MotorModel::none, false));
BENCHMARK_CAPTURE(step_cost, gravity, with_effects(true, false, MotorModel::none, false));
BENCHMARK_CAPTURE(step_cost, gravity_damping, with_effects(true, true, MotorModel::none, false));
BENCHMARK_CAPTURE(step_cost, motor_quasi_static,
                  with_effects(true, true, MotorModel::quasi_static, false));
BENCHMARK_CAPTURE(step_cost, motor_full, with_effects(true, true, MotorModel::full, false));
BENCHMARK_CAPTURE(step_cost, motor_full_rotor, with_effects(true, true, MotorModel::full, true));

BENCHMARK_MAIN();

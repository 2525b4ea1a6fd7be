// Cost of one full step(model, data) (engine/run/step.hpp: detect, active
// set, integrate, events, impacts, stabilise, checks) on scenes with an elbow
// on the table, next to the same scene with contact off, so the price of the
// contact bookkeeping per step can be read off.
//
//   resting: tests' ElbowArm (2 links, torque inputs tau1 = G1/2, tau2 = G2):
//            the elbow rests on the table in static equilibrium.
//   sliding: tests' sliding_arm (3 links, quasi-static servos on slow sines,
//            Baumgarte): the elbow slides along the table.
//
// RK4, 1 ms steps. reset(model, data) once, then step() repeatedly; every
// 500 steps (0.5 s of simulated time) the state is reset so the elbow stays
// on the table (contact on) or near it (contact off). The resets are outside
// the timing (PauseTiming). Counter (contact on): resting = share of steps
// after which the elbow rests; 1 means the scene stayed in contact throughout
// (checked, not assumed).
#include <benchmark/benchmark.h>

#include <algorithm>

#include "engine/run/step.hpp"
#include "support/contact_scenes.hpp"

using namespace elbowsim;

namespace {

constexpr long kStepsPerReset = 500;

Model resting_arm(bool contact) {
  const testing::ElbowArm arm;
  Model m = arm.model(0.5 * arm.G1(), 0.0);
  m.effects.contact = contact;
  finalize(m);
  return m;
}

Model sliding(bool contact) {
  Model m = testing::sliding_arm(Stabilization::baumgarte, 1.0, 1e-3);
  m.effects.contact = contact;
  finalize(m);
  return m;
}

void step_cost(benchmark::State& state, const Model& model) {
  Data data(model);
  reset(model, data);
  long steps = 0, resting = 0;
  for (auto _ : state) {
    step(model, data);
    if (data.failure) {
      state.SkipWithError("the run failed (see Data::failure)");
      break;
    }
    ++steps;
    if (!data.contact.active.empty()) ++resting;
    if (data.step_count >= kStepsPerReset) {
      state.PauseTiming();
      reset(model, data);
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(data.x.data());
  }
  // Contact off: no counter (its cv over the repetitions would be 0/0, NaN in the JSON).
  if (model.effects.contact)
    state.counters["resting"] = static_cast<double>(resting) / static_cast<double>(std::max(steps, 1L));
}

}  // namespace

BENCHMARK_CAPTURE(step_cost, resting_contact_off, resting_arm(false));
BENCHMARK_CAPTURE(step_cost, resting_contact_on, resting_arm(true));
BENCHMARK_CAPTURE(step_cost, sliding_contact_off, sliding(false));
BENCHMARK_CAPTURE(step_cost, sliding_contact_on, sliding(true));

BENCHMARK_MAIN();

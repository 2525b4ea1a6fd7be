// The simulation loop: reset, then step() until the duration, recording every
// N-th step (run/step.hpp has the step itself).
#pragma once

#include <atomic>
#include <functional>

#include "engine/control/experiment.hpp"
#include "engine/run/run_result.hpp"

namespace elbowsim {

struct RunOptions {
  int record_every = 1;  // record every N-th step (and always the first and last)
  // Called now and then with the fraction done (0..1); may be empty.
  std::function<void(double)> progress;
  // Read between steps: once true, the run stops as interrupted (its
  // recording kept). Null: never. The engine installs no signal handler.
  const std::atomic<bool>* stop = nullptr;
};

// Runs the model from its initial state for options.duration under the
// experiment's controller. A run that cannot go on stops: completed = false,
// failure says when and why, and what was recorded so far is kept. A hand
// task that cannot be followed throws PlanError before anything runs.
RunResult simulate(const Model& model, const Experiment& experiment, const RunOptions& options);

// CPU time [s] of the calling thread (RunResult::plan_cpu_seconds, timed studies).
double thread_cpu_seconds();
// An open-loop run: the model's input profiles, no task.
RunResult simulate(const Model& model, const RunOptions& options);

}  // namespace elbowsim

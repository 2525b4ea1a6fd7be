// The simulation loop: initial state -> fixed steps -> recorded samples.
#pragma once

#include <functional>

#include "engine/control/experiment.hpp"
#include "engine/recording/recording.hpp"

namespace elbowsim {

struct RunOptions {
  int record_every = 1;  // record every N-th step (and always the first and last)
  // Called now and then with the fraction done (0..1); may be empty.
  std::function<void(double)> progress;
};

// Runs the model from its initial state for options.duration. A state that
// turns non-finite stops the run: completed = false, failure says when and
// which quantity, and what was recorded so far is kept. A hand task that
// cannot be followed throws PlanError before anything runs.
RunResult simulate(const Model& model, const Experiment& experiment, const RunOptions& options);
// An open-loop run: the model's input profiles, no task.
RunResult simulate(const Model& model, const RunOptions& options);

// Puts the model's initial state into data (t = 0, x, q, qd, current).
void reset_state(const Model& model, Data& data);

// Evaluates the stage outputs (qdd, voltage, current, actuation, energy)
// at the state in data.x without advancing it.
void evaluate_outputs(const Model& model, Data& data);

}  // namespace elbowsim

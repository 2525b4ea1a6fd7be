// What the run checks at t = 0, checked when the scenario loads, so that
// `validate` refuses what `run` would stop at its first step, with the key to
// change: the pose the run starts from (the task's first pose, solved by the
// inverse kinematics as the plan solves it, or initial.q) against the table,
// and the rows the task's elbows hold against the arm's joints
// (engine/control/task_freedom.hpp).
#pragma once

#include "app/scenario/scenario.hpp"
#include "app/scenario/yaml_reader.hpp"

namespace elbowsim::loader {

// Throws ScenarioError at task.elbows (too few joints left for the hand), or
// at the elbow's or link's entry (inside the table at the start pose). A task
// whose first pose cannot be solved is left to the run (its plan fails and
// says why).
void check_start(const Value& root, const Scenario& scenario);

}  // namespace elbowsim::loader

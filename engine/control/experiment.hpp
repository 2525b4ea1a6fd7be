// The paper's experiment, kept beside the plant (Model) as MuJoCo keeps
// controls out of mjModel: the hand task and the controller that tracks it.
// The plan (plan.hpp) turns it into desired joint motion and feed-forward
// voltages before a run; the dynamics never read it.
#pragma once

#include "engine/control/controller.hpp"
#include "engine/control/task.hpp"

namespace elbowsim {

struct Experiment {
  HandTask task;
  ControllerSpec controller;

  // Whether a run needs a plan: a hand task, or a controller that tracks one.
  bool needs_plan() const {
    return task.path != HandTask::Path::none || controller.kind != ControllerSpec::Kind::open_loop;
  }
};

}  // namespace elbowsim

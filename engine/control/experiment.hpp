// The paper's experiment, kept beside the plant (Model) as MuJoCo keeps
// controls out of mjModel: the hand task and the controller that tracks it.
// The plan (plan.hpp) turns it into desired joint motion and feed-forward
// voltages before a run; the dynamics never read it.
#pragma once

#include <memory>

#include "engine/control/controller.hpp"
#include "engine/control/task.hpp"

namespace elbowsim {

struct Experiment {
  HandTask task;
  ControllerSpec controller;
  // What the controller believes the plant is, when it differs from the
  // plant: the plan, its feed-forward and inverse kinematics are built from
  // it. Null: the controller knows the plant exactly.
  std::shared_ptr<const Model> controller_model;

  // The model the plan is built from: the controller's, else the plant's.
  const Model& believed(const Model& plant) const {
    return controller_model ? *controller_model : plant;
  }

  // Whether a run needs a plan: a hand task, or a controller that tracks one.
  bool needs_plan() const {
    return task.path != HandTask::Path::none || controller.kind != ControllerSpec::Kind::open_loop;
  }
};

}  // namespace elbowsim

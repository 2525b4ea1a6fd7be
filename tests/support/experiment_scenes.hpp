// The paper's experiment in code: a redundant 4-link planar arm with an elbow
// sphere at the end of link 1 resting on a table, tracking a hand path.
#pragma once

#include "engine/control/experiment.hpp"
#include "support/models.hpp"

namespace elbowsim::testing {

//                      hand path (2 cm above the table)
//   o shoulder          ~~~~~~
//    \   link 0      o--o--o  hand
//     \            _/
//      o--link 1--O elbow (resting, or 2 cm above for elbow off)
//   ==============================  table (x from 0.3 m)
// The plant and the experiment run on it.
struct ExperimentScene {
  Model model;
  Experiment experiment;
};

struct WritingArm {
  bool elbow_on = true;          // rest the elbow on the table, or hold it 2 cm above (the table stays solid)
  ControllerSpec::Kind controller = ControllerSpec::Kind::pd_feedforward;
  HandTask::Path path = HandTask::Path::line;
  double task_duration = 2.0;    // [s]
  double run_duration = 2.5;     // [s]
  double step = 1e-3;            // [s]
  ExperimentScene scene() const;
};

}  // namespace elbowsim::testing

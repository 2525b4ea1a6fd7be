// engine/control/task_freedom.cpp: the rows the task's kept elbows hold against the arm's
// joints, on the writing arm (4 planar joints, the elbow at the end of link 1) and on arms
// cut short. A planar arm's hand moves in 2 directions (x and z); an elbow on the table
// holds 1 row (its height) or, sticking, 2 (its x and z: y moves with no joint).
#include <doctest/doctest.h>

#include "engine/control/task_freedom.hpp"
#include "support/experiment_scenes.hpp"

using namespace elbowsim;
using namespace elbowsim::testing;

namespace {

// The writing arm, with Coulomb friction (mu 0.6) when `sticking`, its elbow moved to link
// `elbow_link`, its last `drop` links removed (the hand at the new last tip).
ExperimentScene arm(bool sticking, int elbow_link = 1, int drop = 0) {
  ExperimentScene s = WritingArm().scene();
  Model& m = s.model;
  m.effects.friction = sticking;
  m.contact.friction.mu = sticking ? 0.6 : 0.0;
  m.elbows[0].link = elbow_link;
  for (int k = 0; k < drop; ++k) {
    m.joints.pop_back();
    m.links.pop_back();
    m.motors.pop_back();
  }
  m.dof -= drop;
  m.hand_link = m.dof - 1;
  m.hand_point = m.links.back().tip;
  m.damping = Eigen::VectorXd::Constant(m.dof, 0.05);
  m.initial.q = m.initial.q.head(m.dof).eval();
  s.experiment.task.posture = Eigen::VectorXd();
  finalize(m);
  return s;
}

}  // namespace

TEST_CASE("task freedom: the writing arm keeps two joints for its hand, sliding or sticking") {
  for (bool sticking : {false, true}) {
    const ExperimentScene s = arm(sticking);
    const TaskFreedom f = task_freedom(s.model, s.experiment, s.model.initial.q);
    CAPTURE(sticking);
    CHECK(f.joints == 4);
    CHECK(f.sticks == sticking);
    CHECK(f.hand_rank == 2);
    CHECK(f.elbow_rank == (sticking ? 2 : 1));
    CHECK(f.hand_free == 2);
    CHECK(f.fits());
  }
}

TEST_CASE("task freedom: a sticking elbow on link 1 of a 3-joint arm leaves one joint") {
  const ExperimentScene sliding = arm(false, 1, 1), sticking = arm(true, 1, 1);
  const TaskFreedom a = task_freedom(sliding.model, sliding.experiment, sliding.model.initial.q);
  const TaskFreedom b = task_freedom(sticking.model, sticking.experiment, sticking.model.initial.q);
  CHECK(a.joints == 3);
  CHECK(a.elbow_rank == 1);
  CHECK(a.hand_free == 2);  // sliding: the height row leaves 2 of 3 joints
  CHECK(a.fits());
  CHECK(b.elbow_rank == 2);
  CHECK(b.hand_free == 1);  // sticking: its x and z leave 1
  CHECK_FALSE(b.fits());
}

TEST_CASE("task freedom: an elbow on link 0 holds one independent row even when it sticks") {
  // Its centre moves with joint 0 alone: the x and z rows are one row up to scale.
  const ExperimentScene s = arm(true, 0, 1);
  const TaskFreedom f = task_freedom(s.model, s.experiment, s.model.initial.q);
  CHECK(f.elbow_rank == 1);
  CHECK(f.hand_free == 2);
  CHECK(f.fits());
}

TEST_CASE("task freedom: an elbow held above the table holds its clearance row only") {
  ExperimentScene s = arm(true, 1, 1);
  s.experiment.task.elbow_clearance = 0.02;
  const TaskFreedom f = task_freedom(s.model, s.experiment, s.model.initial.q);
  CHECK_FALSE(f.sticks);
  CHECK(f.elbow_rank == 1);
  CHECK(f.fits());
}

TEST_CASE("task freedom: a start laid straight (singular) is not a missing joint") {
  // At q = 0 the 4-link arm lies along x: its hand and elbow move only along z, so the
  // ranks at that pose alone would leave the hand 1 direction (elbow row and hand z
  // dependent). The generic ranks near it give 2.
  const ExperimentScene s = arm(false);
  const TaskFreedom f = task_freedom(s.model, s.experiment, Eigen::VectorXd::Zero(4));
  CHECK(f.hand_rank == 2);
  CHECK(f.hand_free == 2);
  CHECK(f.fits());
}

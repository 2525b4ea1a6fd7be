#include "app/scenario/start_checks.hpp"

#include <sstream>

#include "app/scenario/sections.hpp"
#include "engine/control/plan.hpp"
#include "engine/control/task_freedom.hpp"

namespace elbowsim::loader {

namespace {

// "elbow 'elbow'" or "elbows 'left' and 'right'".
std::string elbow_names(const Model& model, const std::vector<int>& elbows) {
  std::string out = elbows.size() == 1 ? "elbow " : "elbows ";
  for (std::size_t k = 0; k < elbows.size(); ++k)
    out += (k == 0 ? "" : k + 1 == elbows.size() ? " and " : ", ") + std::string("'") +
           model.elbows[std::size_t(elbows[k])].name + "'";
  return out;
}

void check_rows(const Value& root, const Scenario& s, const Model& m, const Eigen::VectorXd& q) {
  const TaskFreedom f = task_freedom(m, s.experiment, q);
  if (f.elbows.empty() || f.fits()) return;
  const double clearance = s.experiment.task.elbow_clearance;
  std::ostringstream msg;
  msg << "the hand's target needs " << f.hand_rank << " joint directions, but "
      << elbow_names(s.model, f.elbows);
  if (clearance > 0)
    msg << " held " << clearance << " m above the table (each one row: its height)";
  else if (f.sticks)
    msg << " kept on the table and sticking (Coulomb friction holds each centre where it lands)";
  else
    msg << " kept on the table (each one row: its height)";
  msg << " take " << f.elbow_rank << " of this " << f.joints << "-joint arm's directions and leave "
      << f.hand_free << " for the hand: the plan could only miss its target. ";
  if (f.sticks)
    msg << "Let the elbow slide (effects.friction: false, or a friction law other than coulomb), "
           "keep fewer elbows on the table (task.elbows), or give the arm more joints";
  else
    msg << "Keep fewer elbows " << (clearance > 0 ? "held" : "on the table")
        << " (task.elbows), or give the arm more joints";
  root.get("task").get("elbows").fail(msg.str());
}

}  // namespace

void check_start(const Value& root, const Scenario& s) {
  // The inverse kinematics and the ranks need the arm and the table, not the
  // contact rows' scratch (sized for every row count: seconds for a long chain).
  Model m = s.model;
  m.effects.contact = false;
  Eigen::VectorXd q = m.initial.q.size() == m.dof ? m.initial.q : Eigen::VectorXd::Zero(m.dof);
  std::string pose = "the initial pose (initial.q)";
  bool solved = false;
  if (s.experiment.needs_plan()) {
    try {
      q = start_pose(m, s.experiment);
      pose = "the task's first pose (initial.q moved by the inverse kinematics onto the hand's "
             "start, where the run starts)";
      solved = true;
    } catch (const PlanError&) {  // the run's plan fails and says why; the rows may be the cause
    }
  }
  if (s.experiment.needs_plan()) check_rows(root, s, m, q);
  if (!s.experiment.needs_plan() || solved) check_initial_penetration(root, s.model, q, pose);
}

}  // namespace elbowsim::loader

#include "engine/control/plan.hpp"

#include <sstream>

#include "engine/contact/lcp.hpp"
#include "engine/control/task_freedom.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/dynamics/rnea.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim {

namespace {

// spec's kp, kd and ki placed by its tuning rule at q0 on `model`; returns
// the rest of what the rule gave (the inertias, the warnings).
TunedGains place_tuned_gains(const Model& model, ConstVec q0, ControllerSpec& spec) {
  TunedGains gains = tune_gains(model, q0, spec.tuning);
  spec.kp = std::move(gains.kp);
  spec.kd = std::move(gains.kd);
  spec.ki = std::move(gains.ki);
  return gains;
}

// "(0.1, 0, 0.3) m at t = 0.5 s"
std::string where(double t, const Eigen::Vector3d& p) {
  return '(' + listed({p.x(), p.y(), p.z()}) + ") m at t = " + significant(t) + " s";
}

IkProblem ik_problem(const Model& model, const HandTask& task, Data& data,
                     const Eigen::VectorXd& q0) {
  IkProblem problem;
  forward_kinematics(model, data, q0);
  for (const std::string& name : task.elbows)
    for (int k = 0; k < int(model.elbows.size()); ++k)
      if (model.elbows[k].name == name) {
        problem.elbows.push_back(k);
        const Elbow& e = model.elbows[k];
        problem.planes.push_back(table_plane_under(model, point_position(data, e.link, e.point)));
      }
  problem.clearance = task.elbow_clearance;
  problem.posture = task.posture.size() == model.dof ? task.posture : q0;
  problem.posture_gain = task.posture_weight;
  problem.q_min = task.q_min;
  problem.q_max = task.q_max;
  return problem;
}

// Every elbow the task rests on the table must rest on a box's top face: its
// contact point (under the sphere) inside the face, not beyond the edge where
// the plane goes on but the table does not.
void check_over_table(const Model& model, Data& data, const IkProblem& problem, double t) {
  if (!model.effects.contact || problem.clearance != 0) return;
  for (std::size_t r = 0; r < problem.elbows.size(); ++r) {
    const Elbow& e = model.elbows[problem.elbows[r]];
    const Eigen::Vector3d contact =
        point_position(data, e.link, e.point) - e.radius * problem.planes[r].normal;
    const TablePlane under = table_plane_under(model, contact);
    if (under.over) continue;
    std::ostringstream msg;
    msg << "the task rests elbow '" << e.name << "' on table box " << problem.planes[r].box
        << ", but at t = " << t << " s its contact point ("
        << listed({contact.x(), contact.y(), contact.z()})
        << ") m is beyond the box's top face: it cannot rest there (move the table, the elbow or "
           "the hand path, or give task.elbow_clearance)";
    throw PlanError(msg.str());
  }
}

std::vector<Eigen::Vector3d> elbow_centres(const Model& model, const Data& data,
                                           const IkProblem& problem) {
  std::vector<Eigen::Vector3d> centres;
  for (int k : problem.elbows)
    centres.push_back(point_position(data, model.elbows[k].link, model.elbows[k].point));
  return centres;
}

// A pose whose row Jacobian's smallest singular value is under this share of
// its largest: the hand all but cannot move along one direction there.
constexpr double kNearSingular = 1e-3;

// The IK result at time t is usable: its rows met within r.tolerance. If not,
// why: the target out of reach (the residual cannot fall further: of the
// arm, near a singular pose, or within the joint limits), or the iterations
// ran out while it still fell. rank: a regular pose's (the task's start); 0:
// this pose's own.
void check(const IkResult& r, double t, const Eigen::Vector3d& target, int rank = 0,
           bool limited = false) {
  if (r.rows_met) return;
  std::ostringstream msg;
  const bool hand = r.hand_residual > r.tolerance;
  if (hand)
    msg << "hand target " << where(t, target);
  else
    msg << "the task's elbows cannot stay in place at t = " << t << " s while the hand is at "
        << where(t, target);
  const double missed = hand ? r.hand_residual : r.elbow_residual;
  if (!r.stationary) {
    msg << ": the inverse kinematics did not converge (still " << missed << " m off after "
        << r.iterations << " iterations; tolerance " << r.tolerance << " m)";
    throw PlanError(msg.str());
  }
  msg << (hand ? " is out of reach" : "") << (limited ? " within the joint limits" : "")
      << ": missed by " << missed << " m (tolerance " << r.tolerance << " m)";
  const double near =
      conditioning(r.singular_values, rank > 0 ? rank : numerical_rank(r.singular_values));
  if (near < kNearSingular)
    msg << ", the arm in a singular pose (stretched toward the target, or folded; "
        << "smallest singular value " << near << " of the largest)";
  throw PlanError(msg.str());
}

// Some joint of q sits at one of the problem's joint limits.
bool at_limit(const IkProblem& problem, const Eigen::VectorXd& q) {
  const bool low = problem.q_min.size() == q.size() && (q.array() <= problem.q_min.array()).any();
  const bool high = problem.q_max.size() == q.size() && (q.array() >= problem.q_max.array()).any();
  return low || high;
}

// Joint rates and accelerations by central differences of the IK samples.
void differentiate(Plan& plan) {
  const std::size_t N = plan.q.size();
  const double h = plan.dt;
  plan.qd.assign(N, Eigen::VectorXd::Zero(plan.q[0].size()));
  plan.qdd = plan.qd;
  for (std::size_t k = 1; k + 1 < N; ++k) {
    plan.qd[k] = (plan.q[k + 1] - plan.q[k - 1]) / (2 * h);
    plan.qdd[k] = (plan.q[k + 1] - 2 * plan.q[k] + plan.q[k - 1]) / (h * h);
  }
}

// The torques that make the plan happen, with the table taking either the
// force that minimises |tau| (f >= 0) or the commanded force; then through
// the motor model to voltages: v = R i + Km qd (+ L di/dt), i = tau / Km.
void feed_forward(const Model& model, const ControllerSpec& controller, Data& data,
                  const IkProblem& problem, Plan& plan) {
  const int n = model.dof,
            p = model.effects.contact && problem.clearance == 0 ? int(problem.elbows.size()) : 0;
  const std::size_t N = plan.q.size();
  std::vector<Eigen::VectorXd> current(N);
  plan.v_ff.assign(N, Eigen::VectorXd::Zero(n));
  plan.f_ff.assign(N, Eigen::VectorXd::Zero(p));
  Matrix3Xd J3(3, n);
  for (std::size_t k = 0; k < N; ++k) {
    forward_kinematics(model, data, plan.q[k]);
    Eigen::VectorXd tau(n);
    inverse_dynamics(model, data, plan.qd[k], plan.qdd[k], {}, tau);
    point_jacobian(model, data, model.hand_link, model.hand_point, J3);
    tau -= J3.transpose() * model.hand_load.force;
    if (p > 0) {
      Eigen::MatrixXd Jc(p, n);
      for (int r = 0; r < p; ++r) {
        const Elbow& e = model.elbows[problem.elbows[r]];
        point_jacobian(model, data, e.link, e.point, J3);
        Jc.row(r) = problem.planes[r].normal.transpose() * J3;
      }
      Eigen::VectorXd f = Eigen::VectorXd::Constant(p, controller.desired_force), w;
      if (controller.kind != ControllerSpec::Kind::force) {
        std::vector<bool> active(p, true);  // min |tau - Jc^T f|^2, f >= 0, as an LCP
        solve_lcp(Jc * Jc.transpose(), -(Jc * tau), model.contact.rank_tolerance, 1e-12, f, w,
                  active);
      }
      tau -= Jc.transpose() * f;
      plan.f_ff[k] = f;
    }
    current[k] = model.has_motor() ? Eigen::VectorXd(tau.cwiseQuotient(model.km)) : tau;
  }
  if (!model.has_motor()) return;
  for (std::size_t k = 0; k < N; ++k) {
    plan.v_ff[k] = model.resistance.cwiseProduct(current[k]) + model.km.cwiseProduct(plan.qd[k]);
    if (model.has_current_state() && k > 0 && k + 1 < N)
      plan.v_ff[k] +=
          model.inductance.cwiseProduct(current[k + 1] - current[k - 1]) / (2 * plan.dt);
  }
}

// Where the task starts on `model`: the initial pose, the hand there (the
// task's `start`) and the IK problem of the task's constraints. Leaves the
// initial pose's kinematics in data.
struct TaskStart {
  Eigen::VectorXd q;
  Eigen::Vector3d hand;
  IkProblem base;
};

TaskStart task_start(const Model& model, const Experiment& experiment, Data& data) {
  TaskStart start;
  start.q =
      model.initial.q.size() == model.dof ? model.initial.q : Eigen::VectorXd::Zero(model.dof);
  forward_kinematics(model, data, start.q);
  start.hand = point_position(data, model.hand_link, model.hand_point);
  start.base = ik_problem(model, experiment.task, data, start.q);
  return start;
}

// The plan passes a near-singular pose (its most singular sample `at`): a
// warning, and the cause a failure of the integration after it leads with
// (step_log.hpp, FailureCause). Over the near-singular stretch around `at`
// (conditioning under kNearSingular, with the neighbours its differences
// reach) the planned joint rates and accelerations peak.
void warn_near_singular(Plan& plan, const std::vector<double>& conditioning_at, long at) {
  const std::size_t k = static_cast<std::size_t>(at), last = plan.q.size() - 1;
  std::size_t first = k, end = k;
  while (first > 0 && conditioning_at[first - 1] < kNearSingular) --first;
  while (end < last && conditioning_at[end + 1] < kNearSingular) ++end;
  first = first > 0 ? first - 1 : 0;
  end = std::min(end + 1, last);
  double rate = 0, acceleration = 0;
  for (std::size_t i = first; i <= end; ++i) {
    rate = std::max(rate, plan.qd[i].cwiseAbs().maxCoeff());
    acceleration = std::max(acceleration, plan.qdd[i].cwiseAbs().maxCoeff());
  }
  const double t = double(at) * plan.dt;
  std::ostringstream peaks, msg, clause;
  peaks.precision(3);
  peaks << "planned joint rates up to " << rate << " rad/s and accelerations up to " << acceleration
        << " rad/s^2 there";
  msg << "the task passes a near-singular pose at t = " << t
      << " s (the arm stretched or folded: the smallest singular value of its task Jacobian is "
      << conditioning_at[k] << " of the largest, so the hand barely moves along one direction "
      << "there); " << peaks.str();
  plan.warnings.push_back(msg.str());
  clause << "the hand task passes near a singular pose at t = " << t
         << " s (the arm stretched or folded; " << peaks.str() << ")";
  using K = Failure::Kind;
  plan.causes.push_back({clause.str(),
                         double(first) * plan.dt,
                         {K::energy_balance, K::diverged, K::current_bound, K::speed_bound,
                          K::penetration, K::step_underflow}});
}

// The IK problem at time t: the hand's target then, the elbows pinned.
IkProblem problem_at(const Experiment& experiment, const TaskStart& start,
                     const std::vector<Eigen::Vector3d>& pins, double t) {
  IkProblem problem = start.base;
  problem.hand = hand_target(experiment.task, start.hand, t).p;
  problem.pins = pins;
  return problem;
}

}  // namespace

std::shared_ptr<const Plan> make_plan(const Model& model, const Experiment& experiment) {
  auto plan = std::make_shared<Plan>();
  Data data(model);
  const TaskStart start = task_start(model, experiment, data);
  const IkProblem& base = start.base;
  plan->dt = experiment.task.plan_step > 0 ? experiment.task.plan_step : model.options.step;
  const long N = std::lround(model.options.duration / plan->dt) + 1;
  Eigen::VectorXd q = start.q;
  // With Coulomb friction a resting elbow sticks: it stays where it lands at
  // the start instead of sliding along its plane (the feed-forward asks no
  // friction force of it, so the plan keeps inside any cone).
  const bool sticks = model.has_coulomb_friction() && base.clearance == 0 && !base.elbows.empty();
  std::vector<Eigen::Vector3d> pins;
  double least = 1;  // the plan's most singular pose: conditioning and sample
  long least_at = 0;
  std::vector<double> conditioning_at;  // [samples]
  int rank = 0;  // the start pose's (taken as regular)
  for (long k = 0; k < N; ++k) {
    const double t = double(k) * plan->dt;
    const IkProblem problem = problem_at(experiment, start, pins, t);
    const IkResult r = solve_ik(model, data, problem, q);
    if (k == 0) rank = numerical_rank(r.singular_values);
    check(r, t, problem.hand, rank, at_limit(problem, r.q));
    conditioning_at.push_back(conditioning(r.singular_values, rank));
    if (conditioning_at.back() < least) least = conditioning_at.back(), least_at = k;
    forward_kinematics(model, data, r.q);
    check_over_table(model, data, problem, t);
    if (k == 0 && sticks) pins = elbow_centres(model, data, problem);
    q = r.q;
    plan->q.push_back(q);
    plan->hand.push_back(problem.hand);
  }
  differentiate(*plan);
  if (least < kNearSingular) warn_near_singular(*plan, conditioning_at, least_at);
  feed_forward(model, experiment.controller, data, base, *plan);
  for (std::size_t r = 0; r < base.elbows.size(); ++r)
    if (base.clearance > 0)
      plan->held.push_back(base.elbows[r]);
    else if (model.effects.contact)
      plan->resting.push_back(base.elbows[r]);
  return plan;
}

Eigen::VectorXd start_pose(const Model& model, const Experiment& experiment) {
  Data data(model);
  const TaskStart start = task_start(model, experiment, data);
  const IkProblem problem = problem_at(experiment, start, {}, 0.0);
  const IkResult r = solve_ik(model, data, problem, start.q);  // make_plan's first sample
  check(r, 0.0, problem.hand, 0, at_limit(problem, r.q));
  return r.q;
}

std::shared_ptr<const Controller> make_controller(const Model& plant,
                                                  const Experiment& experiment) {
  if (!experiment.needs_plan()) return nullptr;
  auto controller = std::make_shared<Controller>();
  controller->spec = experiment.controller;
  controller->plan = make_plan(experiment.believed(plant), experiment);
  if (experiment.controller.tuning.given()) {  // on what the controller believes, at the plan's first pose
    TunedGains rest =
        place_tuned_gains(experiment.believed(plant), controller->plan->q.front(), controller->spec);
    controller->tuning_inertia = std::move(rest.inertia);
    controller->warnings = std::move(rest.warnings);
  }
  // An integral on a joint the table holds would push the elbow into the
  // table for as long as plan and table disagree (a table believed 1 mm low:
  // it winds up to the voltage limit, the motor stalled against the table).
  // Integral action acts on the joints the resting elbows leave free.
  if (controller->spec.integral()) {
    const std::vector<bool> held = joints_held_by_table(experiment.believed(plant), experiment,
                                                        controller->plan->q.front());
    for (int j = 0; j < plant.dof; ++j)
      if (held[std::size_t(j)] && controller->spec.ki[j] != 0) {
        controller->spec.ki[j] = 0;
        controller->integral_held.push_back(j);
      }
  }
  if (experiment.controller_model) controller->plant_start = start_pose(plant, experiment);
  return controller;
}

ControllerSpec gains_before_run(const Model& model, const Experiment& experiment) {
  ControllerSpec spec = experiment.controller;
  if (!spec.tuning.given()) return spec;
  try {
    place_tuned_gains(model, start_pose(model, experiment), spec);
  } catch (const PlanError&) {
  }
  return spec;
}

}  // namespace elbowsim

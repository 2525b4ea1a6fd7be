#include "engine/run/simulator.hpp"

#include <time.h>

#include <chrono>
#include <cmath>

#include "engine/contact/collision.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/run/event_location.hpp"
#include "engine/run/recorder.hpp"
#include "engine/run/step.hpp"
#include "engine/run/validity.hpp"
#include "engine/run/warnings.hpp"
#include "engine/step_grid.hpp"

namespace elbowsim {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

namespace {

// The slot with the most events in events[from..], the lowest on a tie
// (stall messages name it: an elbow, or e.g. the hand's end of the last link).
void busiest_slot(const std::vector<ContactEvent>& events, std::size_t from, Failure& failure) {
  std::vector<long> count;
  for (std::size_t k = from; k < events.size(); ++k) {
    const std::size_t slot = static_cast<std::size_t>(events[k].slot);
    if (slot >= count.size()) count.resize(slot + 1, 0);
    ++count[slot];
  }
  for (std::size_t slot = 0; slot < count.size(); ++slot)
    if (count[slot] > failure.slot_events) {
      failure.slot = static_cast<int>(slot);
      failure.slot_events = count[slot];
    }
}

// Moves what the last step reported into the result.
void collect_log(const Model& model, const Data& data, RunResult& result) {
  result.events.insert(result.events.end(), data.log.events.begin(), data.log.events.end());
  for (const Warning& w : data.log.warnings) {
    result.warnings.push_back(describe(model, w));
    if (w.kind == Warning::Kind::stiff) result.stiff_from = w.t;
  }
}

// A recorded sample, and the energy check on it (run/validity.hpp).
void record(const Model& model, Data& data, RunResult& result) {
  evaluate_outputs(model, data);
  record_sample(model, data, result.trajectory);
  result.max_abs_balance_residual = std::max(
      result.max_abs_balance_residual, std::abs(balance_residual(data.energy, data.energy_initial)));
  track_energy(model, data);
}

// Whether a fixed step ended on a row time k * data.record_interval not yet
// recorded (within step_grid's row tolerance: t accumulates rounding; step.cpp
// cuts steps with the same; a step that reaches a sample instant 1e-13 s later
// would otherwise record the row twice). Remembers k.
bool at_new_row(const Model& model, const Data& data, long& last_row) {
  const double k = std::round(data.t / data.record_interval);
  if (!(k > last_row && step_grid::on_row(data.t, k, data.record_interval, model.options.step)))
    return false;
  last_row = static_cast<long>(k);
  return true;
}

// Adaptive steps do not fall on the recording times k * interval: the rows
// inside the step just taken (from t0) come from the step's dense output
// (adaptive.hpp); a row at the step's end, and the run's last state, are the
// state itself.
void record_rows_in_step(const Model& model, Data& data, RunResult& result, double t0,
                         double interval, long& next_row) {
  const double step = model.options.step, t_end = data.t;
  bool end_recorded = false;
  for (double tr = next_row * interval; step_grid::not_later(tr, t_end, step);
       tr = ++next_row * interval) {
    if (step_grid::not_earlier(tr, t_end, step)) {
      record(model, data, result);
      end_recorded = true;
      continue;
    }
    data.adaptive.x_saved = data.x;
    redo_step(model, data, t0, tr - t0);
    record(model, data, result);
    data.x = data.adaptive.x_saved;
    data.t = t_end;
  }
  if (!end_recorded && finished(model, data)) record(model, data, result);
}

void append(std::vector<std::string>& to, std::vector<std::string> more) {
  for (std::string& w : more) to.push_back(std::move(w));
}

// The controller's gains for the stability of the fixed step (null: open loop).
const ControllerSpec* controller_spec(const Data& data) {
  return data.controller ? &data.controller->spec : nullptr;
}

// What the user needs to know about the run (run/warnings.hpp), after the
// warnings its steps collected: what it did, then its model, then its plan.
void add_warnings(const Model& model, const Data& data, RunResult& result) {
  const Plan* plan = data.controller ? data.controller->plan.get() : nullptr;
  append(result.warnings, saturation_warnings(model, result.saturation));
  append(result.warnings, motor_rating_warnings(model, result.metrics));
  if (plan && model.effects.contact)
    append(result.warnings,
           lift_off_warnings(model, data.contact.geometry, result.events, plan->resting));
  if (model.effects.contact)
    append(result.warnings, unplanned_contact_warnings(model, result.metrics,
                                                       plan ? plan->held : std::vector<int>{}));
  append(result.warnings, hand_error_warnings(model, result.trajectory));
  append(result.warnings, model_warnings(model, controller_spec(data)));
  if (plan) append(result.warnings, plan->warnings);
  if (data.controller) append(result.warnings, data.controller->warnings);
}

// What the warnings report that may explain the run's failure, in the order a
// failure's message looks for its cause (step_log.hpp, FailureCause): the
// fixed step, the plan, the motors' limits.
std::vector<FailureCause> failure_causes(const Model& model, const Data& data,
                                         const RunResult& result) {
  std::vector<FailureCause> causes = stiffness_causes(model, controller_spec(data));
  if (data.controller && data.controller->plan)
    for (const FailureCause& c : data.controller->plan->causes) causes.push_back(c);
  for (FailureCause& c : saturation_causes(model, result.saturation))
    causes.push_back(std::move(c));
  return causes;
}

void finish(const Model& model, Data& data, RunResult& result) {
  result.completed = finished(model, data);
  // Over the whole run: the energy account closed, the elbows the task rests
  // on the table rested.
  if (!data.failure && result.completed) check_energy(model, data);
  if (!data.failure && data.controller && data.controller->plan)
    check_planned_rest(model, data.controller->plan->resting, result.trajectory, data);
  result.valid = !data.failure;
  result.interrupted = data.failure.kind == Failure::Kind::interrupted;
  result.steps = data.step_count;
  result.work = data.work;
  result.final_time = data.t;
  result.energy_initial = data.energy_initial;
  result.energy_final = data.energy;
  result.balance_residual = balance_residual(data.energy, data.energy_initial);
  result.contact = {data.contact.max_abs_C, data.contact.max_abs_Cd, data.contact.dependent_steps};
  result.metrics = compute_metrics(result.trajectory);
  result.saturation = saturation_shares(model, result.trajectory);
  result.failure = describe(model, data.failure, failure_causes(model, data, result));
  add_warnings(model, data, result);
}

}  // namespace

RunResult simulate(const Model& model, const RunOptions& options) {
  return simulate(model, Experiment{}, options);
}

// Steps per window of the stall check: a window whose steps advanced time by
// less than 1 % of theirs on average ends the run (events that cut every step
// to nothing: Zeno). Event location makes a few short steps, never thousands.
constexpr long kStallSteps = 10000;

RunResult simulate(const Model& model, const Experiment& experiment, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const long worlds_before = model.effects.contact ? CollisionWorld::worlds_built() : 0;
  RunResult result;
  result.trajectory = Recording(trajectory_layout(model, experiment.needs_plan()));
  Data data(model);
  // The plan comes from what the controller believes; the plant is `model`.
  const double plan_start = thread_cpu_seconds();
  data.controller = make_controller(model, experiment);  // may throw PlanError
  result.plan_cpu_seconds = thread_cpu_seconds() - plan_start;
  if (const Controller* c = data.controller.get(); c && c->spec.kind != ControllerSpec::Kind::open_loop) {
    const ControllerSpec& spec = c->spec;
    result.gains = {spec.kp, spec.kd,
                    spec.ki.size() ? spec.ki : Eigen::VectorXd::Zero(model.dof),
                    c->tuning_inertia, c->integral_held};
  }
  reset(model, data);
  collect_log(model, data, result);
  record_sample(model, data, result.trajectory);

  const long every = std::max(1, options.record_every);
  const long expected = std::lround(model.options.duration / model.options.step);
  const long progress_every = std::max(1L, expected / 100);
  double window_start = data.t;  // where the current window of kStallSteps steps began
  const bool adaptive = is_adaptive(model.options.integrator);
  const double stall_share = adaptive ? 1e-4 : 1e-2;
  const double interval = every * model.options.step;  // between rows [s]
  if (!adaptive) data.record_interval = interval;  // fixed steps end on the rows (step.cpp)
  long next_row = 1;  // adaptive: the next row to fill
  long last_row = 0;  // fixed steps: the last row recorded
  std::size_t window_events = 0;  // events recorded when the window began
  while (!finished(model, data)) {
    if (options.stop && options.stop->load(std::memory_order_relaxed)) {
      data.failure = Failure{Failure::Kind::interrupted, data.t, data.step_count};
      break;
    }
    const double t0 = data.t;
    step(model, data);
    if (!data.failure && data.step_count % kStallSteps == 0) {  // a run that no longer moves on
      // Adaptive steps may be short for accuracy alone: only a window full of
      // events (a tenth of its steps) is a stall there.
      const bool zeno = !adaptive || result.events.size() - window_events >= kStallSteps / 10;
      if (zeno && data.t - window_start < stall_share * kStallSteps * model.options.step) {
        data.failure = Failure{Failure::Kind::stalled, data.t, data.step_count};
        data.failure.value = data.t - window_start;
        data.failure.limit = kStallSteps;
        busiest_slot(result.events, window_events, data.failure);
        if (data.failure.slot < 0) data.failure.slot = data.contact.last_located_slot;
      }
      window_events = result.events.size();
      window_start = data.t;
    }
    collect_log(model, data, result);
    if (data.failure) break;
    if (adaptive)
      record_rows_in_step(model, data, result, t0, interval, next_row);
    else if (at_new_row(model, data, last_row) || finished(model, data))
      record(model, data, result);
    if (data.failure) break;
    if (options.progress && data.step_count % progress_every == 0)
      options.progress(data.t / model.options.duration);
  }
  finish(model, data, result);
  result.collision_worlds_built =
      model.effects.contact ? CollisionWorld::worlds_built() - worlds_before : 0;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace elbowsim

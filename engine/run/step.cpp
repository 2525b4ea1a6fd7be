#include "engine/run/step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/contact/collision.hpp"
#include "engine/contact/contact_checks.hpp"
#include "engine/contact/impact.hpp"
#include "engine/contact/pad.hpp"
#include "engine/contact/projection.hpp"
#include "engine/control/controller.hpp"
#include "engine/control/digital_loop.hpp"
#include "engine/control/plan.hpp"
#include "engine/dynamics/energy.hpp"
#include "engine/run/active_set.hpp"
#include "engine/run/adaptive.hpp"
#include "engine/run/contact_events.hpp"
#include "engine/run/derivative.hpp"
#include "engine/run/integrator.hpp"
#include "engine/run/joint_stick_slip.hpp"
#include "engine/run/validity.hpp"
#include "engine/state_layout.hpp"
#include "engine/step_grid.hpp"

namespace elbowsim {

namespace {

Eigen::VectorXd or_zeros(const Eigen::VectorXd& v, int n) {
  return v.size() == n ? v : Eigen::VectorXd::Zero(n);
}

// Time to the next recorded row after data.t (infinity without rows).
double time_to_row(const Model& model, const Data& data) {
  if (data.record_interval <= 0) return std::numeric_limits<double>::infinity();
  const double k = step_grid::next_row(data.t, data.record_interval, model.options.step);
  return k * data.record_interval - data.t;
}

// The length of the coming step: the scene's, or what is left before the end
// before the digital loop's next sample instant (the voltage changes there),
// or before the next recorded row.
double step_length(const Model& model, const Data& data) {
  const double left = model.options.duration - data.t;
  const double step = model.options.step;
  double h = step_grid::reached(left, step, step_grid::kFixedEnd) ? step : std::min(step, left);
  const double to_sample = time_to_sample(data);
  if (!step_grid::reached(to_sample, step)) h = std::min(h, to_sample);
  const double to_row = time_to_row(model, data);
  // Only a real cut: t's rounding must not turn a whole step into a 1e-18 shorter one.
  if (to_row < h - step_grid::row_tolerance(step)) h = to_row;
  return h;
}

// The longest step an adaptive integrator may take from here: to the end, to
// the next sample instant, and options.max_step. Unset, that is simulation.step
// in a contact scene (contacts are checked at step ends: a longer step can carry
// a link past a landing, as a longer fixed step would) and a tenth of the run
// otherwise.
double adaptive_limit(const Model& model, const Data& data) {
  const Options& o = model.options;
  const double longest = o.max_step > 0 ? o.max_step : model.effects.contact ? o.step : 0.1 * o.duration;
  double h = std::min(o.duration - data.t, longest);
  const double to_sample = time_to_sample(data);
  if (!step_grid::reached(to_sample, o.step)) h = std::min(h, to_sample);
  return h;
}

// Landings and releases inside the step, impacts, drift control and the
// contact checks, after the state was integrated from data.x_start (t0).
void contact_after_step(const Model& model, Data& data, double t0) {
  locate_first_event(model, data, t0);
  land_touching_slots(model, data);
  if (model.effects.stabilization == Stabilization::projection) stabilise(model, data);
  check_contacts(model, data);
}

}  // namespace

void reset_state(const Model& model, Data& data) {
  const StateLayout s(model);
  data.t = 0;
  data.step_count = 0;
  data.x.setZero();
  data.x.segment(s.q(), s.n) = or_zeros(model.initial.q, s.n);
  data.x.segment(s.qd(), s.n) = or_zeros(model.initial.qd, s.n);
  if (s.current >= 0) data.x.segment(s.current, s.n) = or_zeros(model.initial.current, s.n);
  const Controller* controller = data.controller.get();
  if (!controller || !controller->plan || controller->spec.kind == ControllerSpec::Kind::open_loop)
    return;
  const Plan& plan = *controller->plan;
  data.x.segment(s.q(), s.n) = controller->plant_start.size() == s.n ? controller->plant_start : plan.q[0];
  data.x.segment(s.qd(), s.n) = plan.qd[0];
  if (s.current >= 0 && controller->spec.kind != ControllerSpec::Kind::pd)
    data.x.segment(s.current, s.n) =
        (plan.v_ff[0] - model.km.cwiseProduct(plan.qd[0])).cwiseQuotient(model.resistance);
}

void evaluate_outputs(const Model& model, Data& data) {
  const StateLayout s(model);
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  data.q = data.x.segment(s.q(), s.n);
  data.qd = data.x.segment(s.qd(), s.n);
  if (s.current >= 0) data.current = data.x.segment(s.current, s.n);
  // nonstiff_rates leaves the full di/dt in data.current_rate (motor_stage).
  stored_energy(model, data, data.qd, data.current, data.energy);
  for (const EnergyTermInfo& term : kEnergyTerms)  // the integrated terms from their slots
    if (s.slot(term.term) >= 0) data.energy.*term.value = data.x[s.slot(term.term)];
  if (!model.effects.contact) return;
  data.energy.impact_loss = data.contact.impact_loss;
  data.energy.projection = data.contact.projection_energy;
  if (!model.has_pads()) return;
  data.energy.pad_elastic = pad_elastic_energy(model, data.contact) +
                            relaxing_pad_energy(model, data.contact, data.t);
  data.energy.pad_loss += pad_relaxation_loss(model, data.contact, data.t);
}

void reset(const Model& model, Data& data) {
  check_data(model, data);
  prepare_integrator(model, data);
  reset_state(model, data);
  data.adaptive.h_next = 0;
  data.adaptive.error_last = 1e-4;
  data.adaptive.stiffness = 0;
  data.adaptive.stiff_in_a_row = data.adaptive.nonstiff_in_a_row = 0;
  data.adaptive.stiffness_warned = false;
  data.work = {};
  start_digital_loop(model, data);  // the first sample, before anything reads the voltage
  decide_joint_modes(model, data);
  data.failure = Failure{};
  data.validity = ValidityTrack{};
  data.log.clear();
  if (model.effects.contact) {
    if (!data.contact.world)
      data.contact.world = std::make_shared<CollisionWorld>(model, data.contact.geometry);
    data.contact.last_located_slot = -1;
    select_active_set(model, data);
  }
  evaluate_outputs(model, data);
  data.energy_initial = data.energy;
}

bool finished(const Model& model, const Data& data) {
  // Adaptive steps end on the duration itself (adaptive_limit), so only rounding is left.
  const double share =
      is_adaptive(model.options.integrator) ? step_grid::kRounding : step_grid::kFixedEnd;
  return step_grid::reached(model.options.duration - data.t, model.options.step, share);
}

void step(const Model& model, Data& data) {
  check_data(model, data);
  data.log.clear();
  if (model.effects.contact && !select_active_set(model, data)) return;
  decide_joint_modes(model, data);
  const double t0 = data.t;
  data.x_start = data.x;
  if (!is_adaptive(model.options.integrator))
    integrate_step(model, data, step_length(model, data));
  else if (!adaptive_step(model, data, adaptive_limit(model, data)))
    return;
  locate_joint_event(model, data, t0);
  if (model.effects.contact) contact_after_step(model, data, t0);
  check_step(model, data);  // run/validity.hpp: divergence, bounds, penetration
  if (!data.failure) sample_if_due(model, data);
}

}  // namespace elbowsim

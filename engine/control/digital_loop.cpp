#include "engine/control/digital_loop.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "engine/control/controller.hpp"
#include "engine/data.hpp"
#include "engine/model.hpp"
#include "engine/state_layout.hpp"
#include "engine/step_grid.hpp"

namespace elbowsim {

namespace {

// [rad] the joint-side resolution of joint j's encoder.
double resolution(const Model& model, const SensorSpec& s, int j) {
  const double shaft = 2 * std::numbers::pi / static_cast<double>(s.counts_per_rev);
  const bool motor_side = s.side == SensorSpec::EncoderSide::motor && model.has_motor();
  return motor_side ? shaft / model.motors[static_cast<std::size_t>(j)].gear_ratio : shaft;
}

// The amplifier's resolution: voltage_limit / 2^(bits - 1) per step.
void quantise_voltage(const Model& model, int bits, Eigen::Ref<Eigen::VectorXd> v) {
  if (bits <= 0) return;
  for (int j = 0; j < v.size(); ++j) {
    const double lsb = model.motors[static_cast<std::size_t>(j)].voltage_limit / std::ldexp(1.0, bits - 1);
    v[j] = lsb * std::round(v[j] / lsb);
  }
}

// Integral action's state after the command v computed at this sample:
// each joint adds T e, unless its command is already at the voltage limit
// and e would push it further (conditional integration: the integral does
// not wind up while the motor cannot follow). So the command at sample k
// uses the errors of samples 0 .. k-1.
void integrate_error(const Model& model, Data& data, double T) {
  DigitalLoopState& s = data.loop;
  for (int j = 0; j < s.integral.size(); ++j) {
    const double e = data.q_desired[j] - s.q_measured[j];
    const bool saturated = std::abs(data.voltage[j]) >= model.voltage_limit[j];
    if (saturated && e * data.voltage[j] > 0) continue;
    s.integral[j] += T * e;
  }
}

// One sample at data.t: measure, estimate the velocity, run the control law,
// and pass the command through the delay line to the amplifier.
void sample(const Model& model, Data& data, const DigitalLoopSpec& spec, bool first) {
  DigitalLoopState& s = data.loop;
  const StateLayout layout(model);
  s.q_previous.swap(s.q_measured);
  measure_angles(model, spec, s, data.x.segment(layout.q(), layout.n), s.q_measured);
  if (first) {
    s.velocity = data.x.segment(layout.qd(), layout.n);
  } else {
    const double T = spec.sample_period;
    const double cutoff = spec.sensors.velocity_cutoff;
    const double alpha = cutoff > 0 ? 1 - std::exp(-2 * std::numbers::pi * cutoff * T) : 1.0;
    s.velocity += alpha * ((s.q_measured - s.q_previous) / T - s.velocity);
  }
  control_law(model, data, data.t, s.q_measured, s.velocity);
  quantise_voltage(model, spec.pwm_bits, data.voltage);
  integrate_error(model, data, spec.sample_period);
  if (first) s.pending.assign(static_cast<std::size_t>(spec.delay), data.voltage);
  if (s.pending.empty()) {
    s.held = data.voltage;
  } else {  // a ring: the oldest command goes out, this one takes its place
    Eigen::VectorXd& oldest = s.pending[s.oldest];
    s.held = oldest;
    oldest = data.voltage;
    s.oldest = (s.oldest + 1) % s.pending.size();
  }
  data.voltage = s.held;
  ++s.next_sample;
}

}  // namespace

const DigitalLoopSpec* sampled_loop(const Data& data) {
  const Controller* c = data.controller.get();
  return c && c->plan && c->spec.kind != ControllerSpec::Kind::open_loop && c->spec.loop.sampled()
             ? &c->spec.loop
             : nullptr;
}

void measure_angles(const Model& model, const DigitalLoopSpec& spec, DigitalLoopState& state,
                    ConstVec q, Eigen::Ref<Eigen::VectorXd> out) {
  const SensorSpec& s = spec.sensors;
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int j = 0; j < q.size(); ++j) {
    double angle = q[j];
    if (s.counts_per_rev > 0) {
      const double lsb = resolution(model, s, j);
      angle = lsb * std::round(angle / lsb);
    }
    if (s.noise > 0) angle += s.noise * gauss(state.noise);
    out[j] = angle;
  }
}

void start_digital_loop(const Model& model, Data& data) {
  const DigitalLoopSpec* spec = sampled_loop(data);
  data.loop.next_sample = 0;
  data.loop.pending.clear();
  data.loop.integral.resize(0);
  if (!spec) return;
  data.loop.noise.seed(spec->sensors.seed);
  data.loop.q_measured.setZero(model.dof);
  data.loop.q_previous.setZero(model.dof);
  data.loop.velocity.setZero(model.dof);
  data.loop.held.setZero(model.dof);
  // Integral action keeps a state; a PD loop keeps none (an empty vector).
  if (data.controller->spec.integral()) data.loop.integral.setZero(model.dof);
  data.loop.oldest = 0;
  sample(model, data, *spec, true);
}

void sample_if_due(const Model& model, Data& data) {
  const DigitalLoopSpec* spec = sampled_loop(data);
  if (!spec) return;
  // Instants are k T, not sums of steps: no drift. A step that ends within
  // rounding of the instant (engine/step_grid.hpp) has reached it.
  const double instant = static_cast<double>(data.loop.next_sample) * spec->sample_period;
  if (step_grid::not_earlier(data.t, instant, model.options.step))
    sample(model, data, *spec, false);
}

double time_to_sample(const Data& data) {
  const DigitalLoopSpec* spec = sampled_loop(data);
  if (!spec) return std::numeric_limits<double>::infinity();
  return static_cast<double>(data.loop.next_sample) * spec->sample_period - data.t;
}

}  // namespace elbowsim

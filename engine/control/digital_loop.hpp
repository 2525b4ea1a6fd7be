// A digital control loop: the controller runs at sample instants k T only,
// on what its sensors measure (an encoder's counts plus noise, a velocity
// estimated from them), and the amplifier holds the voltage it computed
// (zero-order hold), `delay` samples later. Between instants the plant runs
// on the held voltage; the integrator steps to every instant (run/step.cpp).
// Continuous control (sample_period 0) is the ideal: the control law at
// every derivative evaluation on the true state.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "engine/eigen_types.hpp"

namespace elbowsim {

struct Model;
struct Data;

struct SensorSpec {
  enum class EncoderSide { motor, joint };
  long counts_per_rev = 0;  // encoder counts per revolution of its shaft; 0: exact angles
  EncoderSide side = EncoderSide::motor;  // motor side: resolution 2 pi / (counts * gear ratio)
  double noise = 0;            // [rad] sigma of Gaussian noise added to each measured joint angle
  double velocity_cutoff = 0;  // [Hz] first-order low-pass on the backward difference; 0: none
  std::uint64_t seed = 1;      // of the noise generator (std::mt19937_64)
};

struct DigitalLoopSpec {
  double sample_period = 0;  // [s] T; 0: continuous control
  int delay = 0;             // [samples] computation delay: a command computed at k T acts at (k + delay) T
  int pwm_bits = 0;          // amplifier resolution: voltage_limit / 2^(bits - 1) steps; 0: exact
  SensorSpec sensors;
  bool sampled() const { return sample_period > 0; }
};

// What the loop keeps between samples (in Data::loop).
struct DigitalLoopState {
  long next_sample = 0;               // index k of the next sample instant k T
  Eigen::VectorXd q_measured;         // [n] the last measured joint angles [rad]
  Eigen::VectorXd q_previous;         // [n] the ones before [rad]
  Eigen::VectorXd velocity;           // [n] the velocity estimate [rad/s]
  Eigen::VectorXd held;               // [n] the voltage the amplifier holds [V]
  Eigen::VectorXd integral;           // [n] sum of T (q_d - q_measured) over past samples [rad s]
  std::vector<Eigen::VectorXd> pending;  // [delay] computed, not yet applied (a ring)
  std::size_t oldest = 0;             // the ring's oldest entry (the next to apply)
  std::mt19937_64 noise;
};

// The loop a run samples: its controller's, when it tracks a plan and has a
// sample rate; null for continuous control (and open loop).
const DigitalLoopSpec* sampled_loop(const Data& data);

// The joint angles the sensors report for the true angles q: rounded to the
// encoder's resolution, plus noise drawn from the loop's generator.
void measure_angles(const Model& model, const DigitalLoopSpec& spec, DigitalLoopState& state,
                    ConstVec q, Eigen::Ref<Eigen::VectorXd> out);

// The loop at t = 0 (reset): the first sample, with the velocity estimate
// started at the true rates (the arm is where the loop has been holding it)
// and the delay line filled with that first command. No-op when continuous.
void start_digital_loop(const Model& model, Data& data);

// After a step: samples when data.t has reached the next instant.
void sample_if_due(const Model& model, Data& data);

// [s] from data.t to the next sample instant; infinity when continuous.
double time_to_sample(const Data& data);

}  // namespace elbowsim

// Open-loop input profiles: one per joint, a motor voltage [V] when the motor
// effect is on, a joint torque [N m] when it is off.
#pragma once

#include <vector>

namespace elbowsim {

struct InputProfile {
  enum class Kind { zero, constant, sine, table, steps };
  Kind kind = Kind::zero;
  double value = 0.0;      // constant
  double amplitude = 0.0;  // sine: offset + amplitude sin(2 pi frequency t + phase)
  double frequency = 0.0;  // [Hz]
  double phase = 0.0;      // [rad]
  double offset = 0.0;
  std::vector<double> times;   // table/steps: strictly increasing [s]
  std::vector<double> values;  // table: linear between points; steps: held from each time on

  // The input at time t; constant extrapolation outside a table.
  double at(double t) const;
};

struct OpenLoopInputs {
  enum class Quantity { voltage, torque };
  Quantity quantity = Quantity::voltage;
  std::vector<InputProfile> joints;  // [dof]; empty means all zero
};

}  // namespace elbowsim

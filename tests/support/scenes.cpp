#include "support/scenes.hpp"

namespace elbowsim::testing {

Model pendulum(IntegratorKind integrator, double step, double duration) {
  Model m = planar_arm({{0.4, 1.3, 0.17, 0.021}, {0.3, 0.8, 0.21, 0.013}});
  m.initial.q = Eigen::Vector2d(0.5, 0.3);
  m.options = {duration, step, integrator, DynamicsMethod::crba};
  finalize(m);
  return m;
}

Model simple_pendulum(IntegratorKind integrator, double step, double duration) {
  Model m = planar_arm({{0.5, 1.0, 0.25, 0.02}});
  m.initial.q = Eigen::VectorXd::Constant(1, 1.0);
  m.options = {duration, step, integrator, DynamicsMethod::crba};
  finalize(m);
  return m;
}

Model driven_arm(IntegratorKind integrator, double step, double duration, double inductance) {
  Model m = planar_arm({{0.4, 1.3, 0.17, 0.021}, {0.3, 0.8, 0.21, 0.013}});
  m.effects.motor = MotorModel::full;
  m.effects.damping = true;
  m.damping = Eigen::Vector2d(0.05, 0.05);
  Motor motor = small_servo();
  motor.inductance = inductance;
  m.motors = {motor, motor};
  InputProfile shoulder, elbow;
  shoulder.kind = elbow.kind = InputProfile::Kind::sine;
  shoulder.offset = 3.0;
  shoulder.amplitude = 2.0;
  shoulder.frequency = 1.0;
  elbow.offset = 1.0;
  elbow.amplitude = 1.5;
  elbow.frequency = 1.7;
  elbow.phase = 0.4;
  m.inputs.joints = {shoulder, elbow};
  m.initial.q = Eigen::Vector2d(0.2, 0.4);
  m.options = {duration, step, integrator, DynamicsMethod::crba};
  finalize(m);
  return m;
}

}  // namespace elbowsim::testing

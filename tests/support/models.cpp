#include "models.hpp"

#include <random>

namespace elbowsim::testing {

Model planar_arm(const std::vector<PlanarLinkSpec>& links) {
  Model m;
  m.name = "planar_arm";
  m.dof = static_cast<int>(links.size());
  double previous_length = 0;
  for (const PlanarLinkSpec& spec : links) {
    Joint joint;
    joint.origin_position = Eigen::Vector3d(previous_length, 0, 0);
    joint.axis = -Eigen::Vector3d::UnitY();
    Link link;
    link.mass = spec.mass;
    link.com = Eigen::Vector3d(spec.com, 0, 0);
    link.inertia = Eigen::Vector3d(1e-4, spec.inertia, spec.inertia).asDiagonal();
    link.tip = Eigen::Vector3d(spec.length, 0, 0);
    m.joints.push_back(joint);
    m.links.push_back(link);
    previous_length = spec.length;
  }
  m.hand_link = m.dof - 1;
  m.hand_point = m.links.back().tip;
  m.effects.motor = MotorModel::none;
  m.effects.damping = false;
  finalize(m);
  return m;
}

Motor small_servo() {
  Motor motor;
  motor.resistance = 2.0;
  motor.inductance = 0.5e-3;
  motor.torque_constant = 0.03;
  motor.gear_ratio = 50;
  motor.rotor_inertia = 5e-7;
  motor.gear_friction = 1e-6;
  motor.voltage_limit = 24;
  return motor;
}

namespace {

// Principal moments of a box of mass m and random sides: always satisfy the
// triangle inequalities.
Eigen::Matrix3d random_inertia(double mass, std::mt19937& rng) {
  std::uniform_real_distribution<double> side(0.02, 0.4);
  const double a = side(rng), b = side(rng), c = side(rng);
  const Eigen::Vector3d principal(b * b + c * c, a * a + c * c, a * a + b * b);
  const Eigen::Matrix3d R = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
  return R * (mass / 12.0 * principal).asDiagonal() * R.transpose();
}

}  // namespace

Model random_chain(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::srand(seed);  // Eigen's Random/UnitRandom use rand()
  std::uniform_real_distribution<double> mass(0.5, 2.0), gear(10, 100);
  Model m;
  m.name = "random_chain";
  m.dof = n;
  for (int i = 0; i < n; ++i) {
    Joint joint;
    joint.origin_position = 0.3 * Eigen::Vector3d::Random();
    joint.origin_rotation = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    joint.axis = Eigen::Vector3d::Random().normalized();
    Link link;
    link.mass = mass(rng);
    link.com = 0.2 * Eigen::Vector3d::Random();
    link.inertia = random_inertia(link.mass, rng);
    m.joints.push_back(joint);
    m.links.push_back(link);
    Motor motor = small_servo();
    motor.gear_ratio = gear(rng);
    m.motors.push_back(motor);
  }
  m.damping = Eigen::VectorXd::Constant(n, 0.05);
  m.hand_link = n - 1;
  m.effects.motor = MotorModel::full;
  finalize(m);
  return m;
}

}  // namespace elbowsim::testing

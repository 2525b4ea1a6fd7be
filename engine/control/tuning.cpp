#include "engine/control/tuning.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numbers>

#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim {

namespace {

// "-31.4 ± 12.1i rad/s" for a pair (printed once), "-62.8 rad/s" for a real pole.
std::string poles_text(const std::vector<std::complex<double>>& poles) {
  std::string out;
  for (const std::complex<double>& p : poles) {
    if (p.imag() < 0) continue;  // its conjugate says it
    if (!out.empty()) out += ", ";
    out += significant(p.real(), 3);
    if (p.imag() > 0) out += " ± " + significant(p.imag(), 3) + "i";
  }
  return out + " rad/s";
}

}  // namespace

JointLoop joint_loop(const Model& model, const Eigen::MatrixXd& mass_matrix, int j) {
  JointLoop loop;
  loop.inertia = mass_matrix(j, j);
  // Small signals drive the load, so the gear passes efficiency x the torque.
  const double eta = model.gear_efficiency[j];
  loop.gain = eta * model.km[j] / model.resistance[j];
  loop.damping = eta * model.km[j] * model.km[j] / model.resistance[j] + model.viscous[j];
  return loop;
}

std::vector<std::complex<double>> closed_loop_poles(const JointLoop& loop, double kp, double kd,
                                                    double ki) {
  // Monic: s^3 + a2 s^2 + a1 s + a0 (PID), s^2 + a2 s + a1 (PD).
  const double a2 = (loop.gain * kd + loop.damping) / loop.inertia;
  const double a1 = loop.gain * kp / loop.inertia;
  const double a0 = loop.gain * ki / loop.inertia;
  Eigen::MatrixXd companion;
  if (ki != 0) {
    companion.setZero(3, 3);
    companion.row(0) << -a2, -a1, -a0;
    companion(1, 0) = companion(2, 1) = 1;
  } else {
    companion.setZero(2, 2);
    companion.row(0) << -a2, -a1;
    companion(1, 0) = 1;
  }
  const Eigen::VectorXcd roots = companion.eigenvalues();
  std::vector<std::complex<double>> poles(roots.data(), roots.data() + roots.size());
  // A double root comes out split by rounding, about sqrt(eps) apart: real.
  for (std::complex<double>& p : poles)
    if (std::abs(p.imag()) < 1e-6 * std::abs(p)) p = {p.real(), 0.0};
  std::sort(poles.begin(), poles.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() < b.real() : a.imag() > b.imag();
  });
  return poles;
}

TunedGains tune_gains(const Model& model, ConstVec q0, const TuningRule& rule) {
  Data data(model);
  forward_kinematics(model, data, q0);
  mass_matrix_crba(model, data);
  const int n = model.dof;
  const double w = 2 * std::numbers::pi * rule.bandwidth;
  const double zeta = rule.damping, alpha = rule.integral;
  TunedGains out;
  out.kp.resize(n), out.kd.resize(n), out.ki.resize(n), out.inertia.resize(n);
  for (int j = 0; j < n; ++j) {
    const JointLoop loop = joint_loop(model, data.mass_matrix, j);
    const double I = loop.inertia, g = loop.gain;
    // The rule: (s^2 + 2 zeta w s + w^2)(s + a), expanded, with a = alpha w;
    // alpha 0 leaves the PD rule.
    const double asked = (2 * zeta + alpha) * w * I;  // the s^2 coefficient x I: g Kd + c
    const double rule_kp = I * (w * w + 2 * zeta * w * (alpha * w)) / g;
    const double rule_kd = (asked - loop.damping) / g;
    const double rule_ki = I * (alpha * w) * w * w / g;
    out.inertia[j] = I;
    if (rule_kd >= 0) {
      out.kp[j] = rule_kp, out.kd[j] = rule_kd, out.ki[j] = rule_ki;
      continue;
    }
    // A joint damped beyond the rule gets Kd 0 and keeps the rule's speed:
    // PID keeps the pair (w, zeta) and moves the integral pole out to
    // a = c / I - 2 zeta w, where the joint's own damping puts it; PD keeps a
    // pole at w and the other at c / I - w (below c / I = 2 w, where that
    // would be the slower one, the pair keeps its natural frequency w, damped
    // c / (2 I w) <= 1 instead).
    const double own = loop.damping / I;
    const double a = alpha > 0 ? own - 2 * zeta * w : 0.0;
    out.kd[j] = 0;
    out.ki[j] = I * a * w * w / g;
    out.kp[j] = alpha == 0 && own > 2 * w ? I * w * (own - w) / g : I * (w * w + 2 * zeta * w * a) / g;
    out.warnings.push_back(
        "controller.tuning: joint " + std::to_string(j) + "'s own damping (back-EMF and friction, " +
        significant(loop.damping, 3) + " N m s/rad) exceeds what the rule asks at " +
        significant(rule.bandwidth, 3) + " Hz (" + significant(asked, 3) +
        " N m s/rad): its Kd is 0 and its closed-loop poles are " +
        poles_text(closed_loop_poles(loop, out.kp[j], 0, out.ki[j])) + ", not the rule's " +
        poles_text(closed_loop_poles(loop, rule_kp, rule_kd, rule_ki)));
  }
  return out;
}

}  // namespace elbowsim

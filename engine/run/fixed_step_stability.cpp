#include "engine/run/fixed_step_stability.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "engine/data.hpp"
#include "engine/dynamics/crba.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/run/integrator.hpp"

namespace elbowsim {

namespace {

// The controller's feedback gains [V/rad, V s/rad] per joint: zero open loop,
// sampled (the amplifier holds the voltage between samples) or without motors.
void feedback_gains(const Model& model, const ControllerSpec* c, Eigen::VectorXd& kp,
                    Eigen::VectorXd& kd) {
  kp = kd = Eigen::VectorXd::Zero(model.dof);
  if (!c || !model.has_motor() || c->kind == ControllerSpec::Kind::open_loop || c->loop.sampled())
    return;
  if (c->kp.size() == model.dof) kp = c->kp;
  if (c->kd.size() == model.dof) kd = c->kd;
}

using Diagonal = Eigen::DiagonalMatrix<double, Eigen::Dynamic>;

}  // namespace

LinearisedArm linearise_arm(const Model& model, const ControllerSpec* controller,
                            const Eigen::VectorXd& q) {
  const int n = model.dof;
  const bool currents = model.has_current_state();
  const int size = currents ? 3 * n : 2 * n;
  LinearisedArm arm;
  arm.n = n;
  arm.lambda = Eigen::VectorXd::Zero(size);
  arm.N = Eigen::MatrixXd::Zero(size, size);
  Data data(model);
  forward_kinematics(model, data, q);
  mass_matrix_crba(model, data);
  const Eigen::LLT<Eigen::MatrixXd> llt(data.mass_matrix);
  const Eigen::MatrixXd M_inv = llt.solve(Eigen::MatrixXd::Identity(n, n));
  Eigen::VectorXd kp, kd;
  feedback_gains(model, controller, kp, kd);
  arm.N.block(0, n, n, n).setIdentity();  // q' = qd
  const Eigen::VectorXd viscous =
      model.viscous.size() == n ? model.viscous : Eigen::VectorXd::Zero(n).eval();
  if (!model.has_motor()) {
    arm.N.block(n, n, n, n) = -M_inv * Diagonal(viscous);
    return arm;
  }
  const Eigen::VectorXd& km = model.km;
  if (!currents) {  // quasi_static: torque Km (v - Km qd) / R with v = -Kp q - Kd qd
    const Eigen::VectorXd gain = km.cwiseQuotient(model.resistance);
    arm.N.block(n, 0, n, n) = -M_inv * Diagonal(gain.cwiseProduct(kp));
    arm.N.block(n, n, n, n) = -M_inv * Diagonal(gain.cwiseProduct(km + kd) + viscous);
    return arm;
  }
  arm.N.block(n, n, n, n) = -M_inv * Diagonal(viscous);
  arm.N.block(n, 2 * n, n, n) = M_inv * Diagonal(km);
  const Eigen::VectorXd over_l = model.inductance.cwiseInverse();
  arm.N.block(2 * n, 0, n, n) = Diagonal(-kp.cwiseProduct(over_l));
  arm.N.block(2 * n, n, n, n) = Diagonal(-(km + kd).cwiseProduct(over_l));
  arm.lambda.tail(n) = -model.resistance.cwiseQuotient(model.inductance);
  return arm;
}

namespace {

// The diagonal weights of one step (as integrator.cpp's coefficients).
struct Weights {
  Eigen::VectorXd e, e_half, p_half, p1, f1, f2, f3;
  Weights(const Eigen::VectorXd& lambda, double h) {
    const Eigen::Index size = lambda.size();
    e = e_half = p_half = p1 = f1 = f2 = f3 = Eigen::VectorXd(size);
    for (Eigen::Index k = 0; k < size; ++k) {
      const double z = lambda[k] * h;
      const double a = phi(1, z), b = phi(2, z), c = phi(3, z);
      e[k] = std::exp(z);
      e_half[k] = std::exp(0.5 * z);
      p_half[k] = 0.5 * h * phi(1, 0.5 * z);
      p1[k] = h * a;
      f1[k] = h * (a - 3.0 * b + 4.0 * c);
      f2[k] = h * (b - 2.0 * c);
      f3[k] = h * (-b + 4.0 * c);
    }
  }
};

// x+ = A x for ETDRK4 (Cox & Matthews), stage by stage as etdrk4_step.
Eigen::MatrixXd etdrk4_map(const LinearisedArm& arm, const Weights& w) {
  const Eigen::MatrixXd& N = arm.N;
  const Eigen::MatrixXd k1 = N;
  const Eigen::MatrixXd a = Eigen::MatrixXd(Diagonal(w.e_half)) + Diagonal(w.p_half) * k1;
  const Eigen::MatrixXd k2 = N * a;
  const Eigen::MatrixXd b = Eigen::MatrixXd(Diagonal(w.e_half)) + Diagonal(w.p_half) * k2;
  const Eigen::MatrixXd k3 = N * b;
  const Eigen::MatrixXd c = Diagonal(w.e_half) * a + Diagonal(w.p_half) * (2.0 * k3 - k1);
  const Eigen::MatrixXd k4 = N * c;
  return Eigen::MatrixXd(Diagonal(w.e)) + Diagonal(w.f1) * k1 + Diagonal(2.0 * w.f2) * (k2 + k3) +
         Diagonal(w.f3) * k4;
}

// x+ = A x for ETD1 (euler); semi_implicit_euler then moves q by h qd+.
Eigen::MatrixXd etd1_map(const LinearisedArm& arm, const Weights& w, bool semi_implicit, double h) {
  Eigen::MatrixXd A = Eigen::MatrixXd(Diagonal(w.e)) + Diagonal(w.p1) * arm.N;
  if (!semi_implicit) return A;
  const int n = arm.n;
  A.topRows(n).setZero();
  A.topLeftCorner(n, n).setIdentity();
  A.topRows(n) += h * A.middleRows(n, n);
  return A;
}

}  // namespace

double amplification_radius(IntegratorKind kind, const LinearisedArm& arm, double h) {
  if (is_adaptive(kind))
    throw std::logic_error("amplification_radius: a fixed-step integrator only");
  const Weights w(arm.lambda, h);
  const Eigen::MatrixXd A = kind == IntegratorKind::rk4
                                ? etdrk4_map(arm, w)
                                : etd1_map(arm, w, kind == IntegratorKind::semi_implicit_euler, h);
  return A.eigenvalues().cwiseAbs().maxCoeff();
}

double stable_step_limit(IntegratorKind kind, const LinearisedArm& arm, double h) {
  auto stable = [&](double step) { return amplification_radius(kind, arm, step) <= kStableRadius; };
  // Bracket the boundary by 10 % steps from h (up to ~1e4 times h either way).
  double below = h, above = h;
  if (stable(h)) {
    for (int k = 0; stable(above); ++k) {
      if (k == 100) return std::numeric_limits<double>::infinity();
      below = above, above *= 1.1;
    }
  } else {
    for (int k = 0; !stable(below); ++k) {
      if (k == 100) return 0;
      above = below, below /= 1.1;
    }
  }
  while (above - below > 1e-3 * below) {
    const double middle = 0.5 * (below + above);
    (stable(middle) ? below : above) = middle;
  }
  return below;
}

FixedStepStability fixed_step_stability(const Model& model, IntegratorKind kind,
                                        const ControllerSpec* controller,
                                        const Eigen::VectorXd& q) {
  FixedStepStability out;
  const double h = model.options.step;
  const LinearisedArm arm = linearise_arm(model, controller, q);
  out.radius = amplification_radius(kind, arm, h);
  out.radius_margin = amplification_radius(kind, arm, kStableMargin * h);
  if (out.radius > kStableRadius) out.stable_step = stable_step_limit(kind, arm, h);
  if (!model.has_current_state()) return out;
  out.fastest = 0;
  for (int j = 1; j < model.dof; ++j)
    if (model.inductance[j] / model.resistance[j] <
        model.inductance[out.fastest] / model.resistance[out.fastest])
      out.fastest = j;
  out.electrical_time = model.inductance[out.fastest] / model.resistance[out.fastest];
  return out;
}

}  // namespace elbowsim

#include "engine/run/adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/run/derivative.hpp"
#include "engine/state_layout.hpp"

namespace elbowsim {

namespace {

// f(t, x) = lambda .* x + N(t, x).
void rates(const Model& model, Data& data, double t, ConstVec x, Eigen::Ref<Eigen::VectorXd> out) {
  nonstiff_rates(model, data, t, x, out);
  out.array() += data.lambda * x.array();
}

// --- dopri5 ------------------------------------------------------------------
// Dormand-Prince 5(4): nodes c, stage weights a, the fifth-order solution's
// weights (the last row of a: first same as last), the difference e between
// the fifth- and fourth-order weights, and the dense-output coefficients d.
namespace dp {
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
}  // namespace dp

// One dopri5 trial step of length h from data.x_start; the new state in
// data.x_b, the error estimate in data.adaptive.error.
void dopri5_trial(const Model& model, Data& data, double h) {
  using namespace dp;
  Data::AdaptiveState& a = data.adaptive;
  const double t = data.t;
  const Eigen::VectorXd& x = data.x_start;
  rates(model, data, t, x, data.k1);
  data.x_a = x + h * a21 * data.k1;
  rates(model, data, t + c2 * h, data.x_a, data.k2);
  data.x_a = x + h * (a31 * data.k1 + a32 * data.k2);
  rates(model, data, t + c3 * h, data.x_a, data.k3);
  data.x_a = x + h * (a41 * data.k1 + a42 * data.k2 + a43 * data.k3);
  rates(model, data, t + c4 * h, data.x_a, data.k4);
  data.x_a = x + h * (a51 * data.k1 + a52 * data.k2 + a53 * data.k3 + a54 * data.k4);
  rates(model, data, t + c5 * h, data.x_a, a.k5);
  data.x_a = x + h * (a61 * data.k1 + a62 * data.k2 + a63 * data.k3 + a64 * data.k4 + a65 * a.k5);
  rates(model, data, t + h, data.x_a, a.k6);
  data.x_b = x + h * (a71 * data.k1 + a73 * data.k3 + a74 * data.k4 + a75 * a.k5 + a76 * a.k6);
  rates(model, data, t + h, data.x_b, a.k7);
  a.error = h * (e1 * data.k1 + e3 * data.k3 + e4 * data.k4 + e5 * a.k5 + e6 * a.k6 + e7 * a.k7);
}

// The continuous extension of the accepted step (Hairer's dopri5 "rcont").
void dopri5_dense(Data& data, double h) {
  using namespace dp;
  Data::AdaptiveState& a = data.adaptive;
  const Eigen::VectorXd& x0 = data.x_start;
  a.dense.col(0) = x0;
  a.dense.col(1) = data.x_b - x0;
  a.dense.col(2) = h * data.k1 - a.dense.col(1);
  a.dense.col(3) = a.dense.col(1) - h * a.k7 - a.dense.col(2);
  a.dense.col(4) = h * (d1 * data.k1 + d3 * data.k3 + d4 * data.k4 + d5 * a.k5 + d6 * a.k6 + d7 * a.k7);
}

// --- ros34pw2 ----------------------------------------------------------------
// (I - h gamma J) K_i = h f(t + c_i h, x + sum_j alpha_ij K_j) + h J sum_j gamma_ij K_j,
// x+ = x + sum b_i K_i, error sum (b_i - bhat_i) K_i (Rang & Angermann 2005, Table 3).
namespace ros {
constexpr double gamma = 4.3586652150845900e-1;
constexpr double alpha[4][3] = {{0, 0, 0},
                                {8.7173304301691801e-1, 0, 0},
                                {8.4457060015369423e-1, -1.1299064236484185e-1, 0},
                                {0, 0, 1}};
constexpr double gam[4][3] = {{0, 0, 0},
                              {-8.7173304301691801e-1, 0, 0},
                              {-9.0338057013044082e-1, 5.4180672388095326e-2, 0},
                              {2.4212380706095346e-1, -1.2232505839045147, 5.4526025533510214e-1}};
// gamma_i = gamma + sum_j gamma_ij, the weights of df/dt.
constexpr double gamma_sum[4] = {gamma, gamma + gam[1][0], gamma + gam[2][0] + gam[2][1],
                                 gamma + gam[3][0] + gam[3][1] + gam[3][2]};
constexpr double c[4] = {0, 8.7173304301691801e-1, 7.3157995778885237e-1, 1};
constexpr double b[4] = {2.4212380706095346e-1, -1.2232505839045147, 1.5452602553351020,
                         4.3586652150845900e-1};
constexpr double bhat[4] = {3.7810903145819369e-1, -9.6042292212423178e-2, 0.5,
                            2.1793326075422950e-1};
}  // namespace ros

// df/dx and df/dt at the step's start (data.x_start, data.t), and f there (adaptive.f0):
// N by forward differences over q, qd and the currents (the energy integrals
// feed nothing back: their columns are zero), lambda exactly on the diagonal.
void ros_jacobian(const Model& model, Data& data) {
  const StateLayout s(model);
  Data::AdaptiveState& a = data.adaptive;
  const Eigen::VectorXd& x = data.x_start;
  nonstiff_rates(model, data, data.t, x, a.f0);
  a.jacobian.setZero();
  const int columns = s.energy;  // q, qd (and i): the components that feed N
  data.x_a = x;
  for (int j = 0; j < columns; ++j) {
    const double delta = std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[j]));
    data.x_a[j] = x[j] + delta;
    nonstiff_rates(model, data, data.t, data.x_a, data.k2);
    data.x_a[j] = x[j];
    a.jacobian.col(j) = (data.k2 - a.f0) / delta;
  }
  a.jacobian.diagonal() += data.lambda.matrix();
  // df/dt (the plan, open-loop inputs): a Rosenbrock method needs it for its
  // order on time-dependent equations (Hairer & Wanner IV.7, (7.4')).
  const double dt = std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(data.t));
  nonstiff_rates(model, data, data.t + dt, x, a.dfdt);
  a.dfdt = (a.dfdt - a.f0) / dt;
  a.f0.array() += data.lambda * x.array();
  ++data.work.jacobians;
}

// One ros34pw2 trial of length h from data.x_start with the step's Jacobian;
// the new state in data.x_b, the error estimate in data.adaptive.error.
void ros_trial(const Model& model, Data& data, double h) {
  using namespace ros;
  Data::AdaptiveState& a = data.adaptive;
  const Eigen::VectorXd& x = data.x_start;
  a.w = -h * gamma * a.jacobian;
  a.w.diagonal().array() += 1.0;
  a.lu.compute(a.w);
  ++data.work.factorisations;
  Eigen::VectorXd* K[4] = {&data.k1, &data.k2, &data.k3, &data.k4};
  for (int i = 0; i < 4; ++i) {
    data.x_a = x;
    data.x_c.setZero();
    for (int j = 0; j < i; ++j) {
      if (alpha[i][j] != 0) data.x_a += alpha[i][j] * *K[j];
      data.x_c += gam[i][j] * *K[j];
    }
    if (i == 0)
      data.x_b = h * a.f0;
    else {
      rates(model, data, data.t + c[i] * h, data.x_a, data.x_b);
      data.x_b *= h;
    }
    if (i > 0) data.x_b.noalias() += h * (a.jacobian * data.x_c);
    data.x_b += (h * h * gamma_sum[i]) * a.dfdt;
    *K[i] = a.lu.solve(data.x_b);
  }
  data.x_b = x;
  a.error.setZero();
  for (int i = 0; i < 4; ++i) {
    data.x_b += b[i] * *K[i];
    a.error += (b[i] - bhat[i]) * *K[i];
  }
}

// Order of the error estimate's leading term (the embedded method's order + 1).
int estimate_order(IntegratorKind k) { return k == IntegratorKind::dopri5 ? 5 : 3; }

void trial(const Model& model, Data& data, double h) {
  if (model.options.integrator == IntegratorKind::dopri5)
    dopri5_trial(model, data, h);
  else
    ros_trial(model, data, h);
}

// Hairer's stiffness test on the accepted dopri5 step of length h: data.x_a
// holds its sixth stage and data.x_b the solution, both at t + h, and k6, k7
// their rates, so that (k7 - k6) / (x7 - x6) is the Jacobian's action along
// their difference, which the stiffest mode dominates. Warns once per run.
void watch_stiffness(const Model& model, Data& data, double h) {
  Data::AdaptiveState& a = data.adaptive;
  const int n = StateLayout(model).controlled;
  const double apart = (data.x_b.head(n) - data.x_a.head(n)).squaredNorm();
  if (apart <= 0) return;
  a.stiffness = h * std::sqrt((a.k7.head(n) - a.k6.head(n)).squaredNorm() / apart);
  if (a.stiffness > kStiffEdge) {
    a.nonstiff_in_a_row = 0;
    if (++a.stiff_in_a_row < kStiffSteps || a.stiffness_warned) return;
    Warning w;
    w.kind = Warning::Kind::stiff;
    w.t = data.t + h;
    w.value = a.stiffness;
    w.step = h;
    data.log.warnings.push_back(w);
    a.stiffness_warned = true;
  } else if (++a.nonstiff_in_a_row >= kNonstiffSteps) {
    a.stiff_in_a_row = 0;
  }
}

}  // namespace

double error_norm(const Options& options, ConstVec e, ConstVec x0, ConstVec x1) {
  double sum = 0;
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    const double scale = options.atol + options.rtol * std::max(std::abs(x0[k]), std::abs(x1[k]));
    sum += (e[k] / scale) * (e[k] / scale);
  }
  return std::sqrt(sum / static_cast<double>(e.size()));
}

bool adaptive_step(const Model& model, Data& data, double h_max) {
  const Options& o = model.options;
  Data::AdaptiveState& a = data.adaptive;
  data.x_start = data.x;
  if (o.integrator == IntegratorKind::ros34pw2) ros_jacobian(model, data);
  const double proposed = a.h_next > 0 ? a.h_next : o.step;
  double h = std::min(proposed, h_max);
  const double order = estimate_order(o.integrator);
  // Hairer's PI control for dopri5 (beta 0.04), plain I control for ros34pw2.
  const double beta = o.integrator == IntegratorKind::dopri5 ? 0.04 : 0.0;
  const double alpha = 1.0 / order - 0.75 * beta;
  for (;;) {
    trial(model, data, h);
    const int weighed = StateLayout(model).controlled;
    const double err = error_norm(o, data.adaptive.error.head(weighed), data.x_start.head(weighed),
                                  data.x_b.head(weighed));
    if (err <= 1.0) {
      const double factor =
          std::clamp(0.9 * std::pow(std::max(err, 1e-10), -alpha) * std::pow(a.error_last, beta), 0.2, 10.0);
      // A step cut short by h_max (a sample instant, the end) says nothing
      // against the longer step proposed before it.
      a.h_next = h < proposed ? std::max(proposed, h * factor) : h * factor;
      a.error_last = std::max(err, 1e-4);
      break;
    }
    ++data.work.rejected;
    const double shrink = std::isfinite(err) ? std::max(0.2, 0.9 * std::pow(err, -1.0 / order)) : 0.2;
    h *= shrink;
    if (h <= 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(data.t))) {
      data.failure = Failure{Failure::Kind::step_underflow, data.t, data.step_count};
      data.failure.value = h;
      data.x = data.x_start;
      return false;
    }
  }
  a.h_last = h;
  if (o.integrator == IntegratorKind::dopri5) {
    dopri5_dense(data, h);
    watch_stiffness(model, data, h);
  }
  data.x = data.x_b;
  data.t += h;
  ++data.step_count;
  return true;
}

void adaptive_redo(const Model& model, Data& data, double t0, double tau) {
  Data::AdaptiveState& a = data.adaptive;
  data.t = t0;
  if (model.options.integrator == IntegratorKind::ros34pw2) {
    ros_trial(model, data, tau);
    data.x = data.x_b;
  } else {
    const double theta = tau / a.h_last, rest = 1.0 - theta;
    data.x = a.dense.col(0) +
             theta * (a.dense.col(1) +
                      rest * (a.dense.col(2) + theta * (a.dense.col(3) + rest * a.dense.col(4))));
  }
  data.t = t0 + tau;
}

}  // namespace elbowsim

#include "integrator.hpp"

#include <cmath>

#include "derivative.hpp"
#include "state_vector.hpp"

namespace elbowsim {

double phi(int k, double z) {
  // Taylor series near zero avoids the cancellation in (e^z - 1 - ...)/z^k.
  if (std::abs(z) < 0.5) {
    double term = 1.0, sum = 0.0;
    for (int j = 1; j <= k; ++j) term /= j;  // 1/k!
    for (int j = 0; j < 30; ++j) {
      sum += term;
      term *= z / (j + k + 1);
    }
    return sum;
  }
  const double e = std::exp(z);
  if (k == 1) return (e - 1.0) / z;
  if (k == 2) return (e - 1.0 - z) / (z * z);
  return (e - 1.0 - z - 0.5 * z * z) / (z * z * z);
}

void prepare_integrator(const Model& model, Data& data) {
  stiff_rates(model, data.lambda);
  const double h = model.options.step;
  for (Eigen::Index c = 0; c < data.lambda.size(); ++c) {
    const double z = data.lambda[c] * h;
    const double p1 = phi(1, z), p2 = phi(2, z), p3 = phi(3, z);
    data.exp_h[c] = std::exp(z);
    data.exp_half[c] = std::exp(0.5 * z);
    data.phi1_half[c] = 0.5 * h * phi(1, 0.5 * z);
    data.phi1_h[c] = h * p1;
    // Cox-Matthews ETDRK4 weights; h/6, h/6, h/6 when z = 0.
    data.f1[c] = h * (p1 - 3.0 * p2 + 4.0 * p3);
    data.f2[c] = h * (p2 - 2.0 * p3);
    data.f3[c] = h * (-p2 + 4.0 * p3);
  }
}

namespace {

void euler_step(const Model& model, Data& data) {
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  data.x = (data.exp_h * data.x.array() + data.phi1_h * data.k1.array()).matrix();
}

void semi_implicit_euler_step(const Model& model, Data& data) {
  const StateLayout s(model);
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  const int rest = s.size - s.n;  // qd, currents, energies: ETD1
  data.x.tail(rest) = (data.exp_h.tail(rest) * data.x.tail(rest).array() +
                       data.phi1_h.tail(rest) * data.k1.tail(rest).array())
                          .matrix();
  data.x.head(s.n) += model.options.step * data.x.segment(s.qd(), s.n);
}

void etdrk4_step(const Model& model, Data& data) {
  const double h = model.options.step, t = data.t;
  const auto x = data.x.array();
  nonstiff_rates(model, data, t, data.x, data.k1);
  data.x_a = (data.exp_half * x + data.phi1_half * data.k1.array()).matrix();
  nonstiff_rates(model, data, t + 0.5 * h, data.x_a, data.k2);
  data.x_b = (data.exp_half * x + data.phi1_half * data.k2.array()).matrix();
  nonstiff_rates(model, data, t + 0.5 * h, data.x_b, data.k3);
  data.x_c = (data.exp_half * data.x_a.array() +
              data.phi1_half * (2.0 * data.k3.array() - data.k1.array()))
                 .matrix();
  nonstiff_rates(model, data, t + h, data.x_c, data.k4);
  data.x = (data.exp_h * x + data.f1 * data.k1.array() +
            2.0 * data.f2 * (data.k2.array() + data.k3.array()) + data.f3 * data.k4.array())
               .matrix();
}

}  // namespace

void integrate_step(const Model& model, Data& data) {
  switch (model.options.integrator) {
    case IntegratorKind::euler: euler_step(model, data); break;
    case IntegratorKind::semi_implicit_euler: semi_implicit_euler_step(model, data); break;
    case IntegratorKind::rk4: etdrk4_step(model, data); break;
  }
  ++data.steps;
  data.t = static_cast<double>(data.steps) * model.options.step;
}

}  // namespace elbowsim

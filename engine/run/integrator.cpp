#include "engine/run/integrator.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/run/derivative.hpp"
#include "engine/state_layout.hpp"

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

namespace {

using Coefficients = Data::EtdCoefficients;

void compute_coefficients(const Eigen::ArrayXd& lambda, double h, Coefficients& c) {
  c.h = h;
  for (Eigen::Index k = 0; k < lambda.size(); ++k) {
    const double z = lambda[k] * h;
    const double p1 = phi(1, z), p2 = phi(2, z), p3 = phi(3, z);
    c.exp_h[k] = std::exp(z);
    c.exp_half[k] = std::exp(0.5 * z);
    c.phi1_half[k] = 0.5 * h * phi(1, 0.5 * z);
    c.phi1_h[k] = h * p1;
    // Cox-Matthews ETDRK4 weights; h/6, h/6, h/6 when z = 0.
    c.f1[k] = h * (p1 - 3.0 * p2 + 4.0 * p3);
    c.f2[k] = h * (p2 - 2.0 * p3);
    c.f3[k] = h * (-p2 + 4.0 * p3);
  }
}

void euler_step(const Model& model, Data& data, const Coefficients& c) {
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  data.x = (c.exp_h * data.x.array() + c.phi1_h * data.k1.array()).matrix();
}

void semi_implicit_euler_step(const Model& model, Data& data, const Coefficients& c) {
  const StateLayout s(model);
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  const int rest = s.size - s.n;  // qd, currents, energies: ETD1
  data.x.tail(rest) = (c.exp_h.tail(rest) * data.x.tail(rest).array() +
                       c.phi1_h.tail(rest) * data.k1.tail(rest).array())
                          .matrix();
  data.x.head(s.n) += c.h * data.x.segment(s.qd(), s.n);
}

void etdrk4_step(const Model& model, Data& data, const Coefficients& c) {
  const double h = c.h, t = data.t;
  const auto x = data.x.array();
  nonstiff_rates(model, data, t, data.x, data.k1);
  data.x_a = (c.exp_half * x + c.phi1_half * data.k1.array()).matrix();
  nonstiff_rates(model, data, t + 0.5 * h, data.x_a, data.k2);
  data.x_b = (c.exp_half * x + c.phi1_half * data.k2.array()).matrix();
  nonstiff_rates(model, data, t + 0.5 * h, data.x_b, data.k3);
  data.x_c =
      (c.exp_half * data.x_a.array() + c.phi1_half * (2.0 * data.k3.array() - data.k1.array()))
          .matrix();
  nonstiff_rates(model, data, t + h, data.x_c, data.k4);
  data.x = (c.exp_h * x + c.f1 * data.k1.array() +
            2.0 * c.f2 * (data.k2.array() + data.k3.array()) + c.f3 * data.k4.array())
               .matrix();
}

void step_with(const Model& model, Data& data, const Coefficients& c) {
  switch (model.options.integrator) {
    case IntegratorKind::euler: euler_step(model, data, c); break;
    case IntegratorKind::semi_implicit_euler: semi_implicit_euler_step(model, data, c); break;
    case IntegratorKind::rk4: etdrk4_step(model, data, c); break;
    case IntegratorKind::dopri5:
    case IntegratorKind::ros34pw2:
      // They choose their own step lengths (adaptive.hpp); step() calls them.
      throw std::logic_error("integrate_step: the adaptive integrators step by adaptive_step()");
  }
  ++data.step_count;
  data.t += c.h;
}

}  // namespace

void prepare_integrator(const Model& model, Data& data) {
  stiff_rates(model, data.lambda);
  compute_coefficients(data.lambda, model.options.step, data.etd_full);
}

void integrate_step(const Model& model, Data& data) { step_with(model, data, data.etd_full); }

void integrate_step(const Model& model, Data& data, double h) {
  if (h == data.etd_full.h) return step_with(model, data, data.etd_full);
  if (h != data.etd_short.h) compute_coefficients(data.lambda, h, data.etd_short);
  step_with(model, data, data.etd_short);
}

}  // namespace elbowsim

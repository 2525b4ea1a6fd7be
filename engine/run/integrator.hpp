// Fixed-step integrators for x' = lambda .* x + N(t, x) (derivative.hpp).
//
// The linear part lambda = -R/L of the motor currents can be far faster than
// the step (L = 1e-5 H, R = 1 ohm: L/R = 10 us against a 1 ms step), so every
// integrator treats it exactly, by exponential time differencing (ETD):
//   euler                ETD1:    x+ = e^{z} x + h phi1(z) N(x)           (order 1)
//   semi_implicit_euler  qd, i and energies by ETD1 first, then q+ = q + h qd+
//                        (symplectic Euler for the arm; order 1)
//   rk4                  ETDRK4 of Cox & Matthews (2002)                   (order 4)
// with z = lambda h. Where lambda = 0 (all mechanical components) these are
// exactly explicit Euler, symplectic Euler and classical RK4.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Precomputes the per-component ETD coefficients for the model's step.
void prepare_integrator(const Model& model, Data& data);

// Advances data.x from data.t by one step of the model's length (or by
// h < step, for event location and the last step). Allocates nothing.
void integrate_step(const Model& model, Data& data);
void integrate_step(const Model& model, Data& data, double h);

// phi_k(z) = sum_{j>=0} z^j / (j + k)!, the ETD weight functions (k = 1, 2, 3).
double phi(int k, double z);

}  // namespace elbowsim

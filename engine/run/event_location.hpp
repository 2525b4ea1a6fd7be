// Locating an event inside a step: the step is redone from its start
// (data.x_start at t0) over shorter lengths until the event function's sign
// change is bracketed within a tolerance. Contact events (run/contact_events) and
// joint stick-slip (run/joint_stick_slip) share it.
#pragma once

#include <algorithm>

#include "engine/data.hpp"

namespace elbowsim {

// Redoes the step from data.x_start (time t0) over tau; the redone step
// replaces the one already counted.
void redo_step(const Model& model, Data& data, double t0, double tau);

// Illinois (modified regula falsi) on value(model, data) >= 0 before the
// event, < 0 after it, over the step [t0, t0 + h] that data.x ends (its
// value there is negative). Each evaluation integrates from the step start.
// Returns a step length just past the event, within `tolerance` [s], and
// leaves data at the end of that shortened step.
template <class Value>
double locate_crossing(const Model& model, Data& data, double t0, double h, double tolerance,
                       const Value& value) {
  auto value_at = [&](double tau) {
    redo_step(model, data, t0, tau);
    return value(model, data);
  };
  double lo = 0, hi = h, g_hi = value(model, data);
  const double t_end = data.t;
  data.x.swap(data.x_start);
  data.t = t0;
  double g_lo = value(model, data);
  data.x.swap(data.x_start);
  data.t = t_end;
  int side = 0;
  while (hi - lo > tolerance) {
    double tau = hi - g_hi * (hi - lo) / (g_hi - g_lo);
    if (!(tau > lo && tau < hi)) tau = 0.5 * (lo + hi);
    // Half a tolerance inside the bracket: a converged estimate then closes
    // it from one side in one more evaluation (instead of bisecting there).
    tau = std::clamp(tau, lo + 0.5 * tolerance, hi - 0.5 * tolerance);
    const double g = value_at(tau);
    if (g < 0) {
      hi = tau, g_hi = g;
      if (side == -1) g_lo *= 0.5;
      side = -1;
    } else {
      lo = tau, g_lo = g;
      if (side == 1) g_hi *= 0.5;
      side = 1;
    }
  }
  value_at(hi);
  return hi;
}

}  // namespace elbowsim

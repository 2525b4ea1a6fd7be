#include "engine/contact/events.hpp"

#include "engine/contact/detection.hpp"
#include "engine/run/derivative.hpp"
#include "engine/run/integrator.hpp"

namespace elbowsim {

namespace {

constexpr double kReleaseForce = 1e-9;  // [N] a resting slot pulled harder than this releases

// Landing: the slot's signed distance; release: its normal force (both
// change sign at the event).
double event_value(const Model& model, Data& data, int slot, bool landing) {
  if (landing) {
    detect_contacts(model, data);
    return data.contact.detected[slot].distance;
  }
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  for (std::size_t r = 0; r < data.contact.active.size(); ++r)
    if (data.contact.active[r] == slot) return data.contact.fn[r];
  return 0.0;
}

// Redoes the step from its start over tau <= h; the redone step replaces the
// one already counted.
void redo_step(const Model& model, Data& data, double t0, double tau) {
  data.x = data.x_start;
  data.t = t0;
  integrate_step(model, data, tau);
  --data.step_count;
}

// Illinois (modified regula falsi) on the event function over the step, each
// evaluation integrating from the step start; returns a time just past the
// event, within model.contact.locate_tolerance.
double locate(const Model& model, Data& data, double t0, double h, int slot, bool landing) {
  auto value_at = [&](double tau) {
    redo_step(model, data, t0, tau);
    return event_value(model, data, slot, landing);
  };
  double lo = 0, hi = h, g_hi = event_value(model, data, slot, landing);
  const double t_end = data.t;
  data.x.swap(data.x_start);
  data.t = t0;
  double g_lo = event_value(model, data, slot, landing);
  data.x.swap(data.x_start);
  data.t = t_end;
  int side = 0;
  while (hi - lo > model.contact.locate_tolerance) {
    double tau = hi - g_hi * (hi - lo) / (g_hi - g_lo);
    if (!(tau > lo + 1e-3 * (hi - lo) && tau < hi - 1e-3 * (hi - lo))) tau = 0.5 * (lo + hi);
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

}  // namespace

void locate_first_event(const Model& model, Data& data, double t0) {
  ContactData& c = data.contact;
  const double h = data.t - t0;
  detect_contacts(model, data);
  if (model.contact.events != EventTiming::locate) return;
  int first = -1;
  bool first_is_landing = true;
  double first_time = h;
  for (int k = 0; k < c.slots(); ++k) {
    const bool landing = !c.resting[k] && c.detected[k].distance < 0 && normal_speed(model, data, k) < 0;
    // A force that is zero to rounding (a row that carries nothing) is no release:
    // locating it would shorten every step to the locate tolerance.
    const bool releasing =
        c.resting[k] && !landing && event_value(model, data, k, false) < -kReleaseForce;
    if (!landing && !releasing) continue;
    const double tau = locate(model, data, t0, h, k, landing);
    if (tau < first_time || first < 0) first = k, first_time = tau, first_is_landing = landing;
    // Back to the whole step, for the next slot's test.
    redo_step(model, data, t0, h);
    detect_contacts(model, data);
  }
  if (first < 0) return;
  redo_step(model, data, t0, first_time);
  detect_contacts(model, data);
  if (first_is_landing) return;
  c.resting[first] = false;
  data.log.events.push_back({data.t, first, ContactEvent::Kind::release, 0, 0, 0});
}

}  // namespace elbowsim

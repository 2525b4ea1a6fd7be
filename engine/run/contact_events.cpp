#include "engine/run/contact_events.hpp"

#include <algorithm>

#include "engine/contact/detection.hpp"
#include "engine/contact/pad.hpp"
#include "engine/contact/stick_slip.hpp"
#include "engine/run/derivative.hpp"
#include "engine/run/event_location.hpp"
#include "engine/run/integrator.hpp"

namespace elbowsim {

namespace {

constexpr double kReleaseForce = 1e-9;  // [N] a resting slot pulled harder than this releases
constexpr double kConeForce = 1e-9;     // [N] a sticking slot's force this far outside its cone slips

enum class Event {
  landing,     // a free slot's distance turns negative
  release,     // a resting slot's normal force turns negative
  slip_start,  // a sticking slot's force leaves its cone: mu f_n - |f_t| < 0
  slip_stop,   // a sliding slot's speed along its slip turns negative
  feature,     // a resting slot's ball leaves the face, edge or corner of its frame
};

double normal_force(const ContactData& c, int slot) {
  for (std::size_t r = 0; r < c.active.size(); ++r)
    if (c.active[r] == slot) return c.fn[static_cast<Eigen::Index>(r)];
  return 0.0;
}

// How far a free slot is past where it lands [m] (negative: landed). A slot
// that started the step in the table by rounding (a free slot touching, whose
// force the active set found zero: it was leaving) lands when it goes deeper
// than it started: measured from 0 it would have "landed" at the step's start
// and, not approaching there, never been landed, so every following step was
// cut to the locate tolerance again (a stall: a hand grazing the table while
// its motors' currents turned it back down within the step).
// A padded slot lands on its pad's surface, which may still be coming back up
// (pad.hpp); its start distance is to that surface too (active_set.cpp).
double landing_depth(const Model& model, const Data& data, int slot) {
  const ContactData& c = data.contact;
  return pad_gap(model, c, slot, data.t) - std::min(0.0, c.start_distance[static_cast<std::size_t>(slot)]);
}

// The event function (its sign changes at the event) at the state in data.x.
double event_value(const Model& model, Data& data, int slot, Event event) {
  switch (event) {
    case Event::landing:
      detect_contacts(model, data);
      return landing_depth(model, data, slot);
    case Event::feature:
      detect_contacts(model, data);  // forward kinematics
      return feature_margin(model, data, slot);
    default: break;
  }
  nonstiff_rates(model, data, data.t, data.x, data.k1);
  if (event == Event::slip_start) return cone_margin(model, data, slot);
  if (event == Event::slip_stop) return slip_speed(model, data, slot);
  return normal_force(data.contact, slot);
}

// The event a slot meets at the end of the step, if any (at most one per
// slot, in this order: a slot that lands has no rows; one that releases needs
// no friction; a change of feature is tested last).
bool happens(const Model& model, const Data& data, int k, Event& event) {
  const ContactData& c = data.contact;
  if (!c.resting[k]) {
    event = Event::landing;
    if (const Pad* pad = slot_pad(model, c, k))  // its surface may be coming up (pad.hpp)
      return landing_depth(model, data, k) < 0 &&
             pad_force(*pad, c.detected[k].distance, normal_speed(model, data, k)) > 0;
    return landing_depth(model, data, k) < 0 &&
           normal_speed(model, data, k) < -model.contact.separation_velocity;
  }
  // A force that is zero to rounding (a row that carries nothing) is no release:
  // locating it would shorten every step to the locate tolerance.
  event = Event::release;
  if (normal_force(c, k) < -kReleaseForce) return true;
  if (model.has_coulomb_friction()) {
    event = c.sticking[k] ? Event::slip_start : Event::slip_stop;
    if (c.sticking[k] ? cone_margin(model, data, k) < -kConeForce : slip_speed(model, data, k) < 0)
      return true;
  }
  event = Event::feature;
  return feature_margin(model, data, k) < 0;
}

// Every event at the end of the step, into data.contact.events_found (slot
// and event), from one evaluation of the rates there.
void find_events(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.events_found.clear();
  bool rates = false;
  for (int k = 0; k < c.slots(); ++k) {
    if (c.resting[k] && !rates) {
      nonstiff_rates(model, data, data.t, data.x, data.k1);  // forces and rows at the end
      rates = true;
    }
    Event event;
    if (happens(model, data, k, event)) c.events_found.push_back({k, static_cast<int>(event)});
  }
}

// The event's time, to model.contact.locate_tolerance (run/event_location.hpp).
double locate(const Model& model, Data& data, double t0, double h, int slot, Event event) {
  return locate_crossing(model, data, t0, h, model.contact.locate_tolerance,
                         [slot, event](const Model& m, Data& d) { return event_value(m, d, slot, event); });
}

// What an event changes at its time (a landing is the impact stage's; a
// stopped slip or a new feature is the next step's start).
void apply_event(const Model& model, Data& data, int slot, Event event) {
  ContactData& c = data.contact;
  if (event == Event::release) {
    detect_contacts(model, data);  // the pad's depth where it lets go
    book_pad_release(model, data, slot);
    c.resting[slot] = false;
    data.log.events.push_back({data.t, slot, ContactEvent::Kind::release, 0, 0, 0});
  } else if (event == Event::slip_start) {
    // Against the force that left the cone.
    nonstiff_rates(model, data, data.t, data.x, data.k1);
    const Eigen::Vector3d f = friction_force(model, data, slot);
    c.sticking[slot] = 0;
    if (f.norm() > 0) c.slip[slot] = -f.normalized();
    data.log.events.push_back({data.t, slot, ContactEvent::Kind::slip, 0, 0, 0});
  } else if (event == Event::slip_stop) {
    c.slip_stopped[slot] = 1;
  }
}

}  // namespace

void locate_first_event(const Model& model, Data& data, double t0) {
  ContactData& c = data.contact;
  const double h = data.t - t0;
  detect_contacts(model, data);
  if (model.contact.events != EventTiming::locate) return;
  find_events(model, data);
  int first = -1;
  Event first_event = Event::landing;
  double first_time = h;
  for (std::size_t i = 0; i < c.events_found.size(); ++i) {
    if (i > 0) redo_step(model, data, t0, h);  // back to the whole step
    const auto [k, kind] = c.events_found[i];
    const Event event = static_cast<Event>(kind);
    const double tau = locate(model, data, t0, h, k, event);
    if (tau < first_time || first < 0) first = k, first_time = tau, first_event = event;
  }
  if (first < 0) return;
  c.last_located_slot = first;
  redo_step(model, data, t0, first_time);
  apply_event(model, data, first, first_event);
  detect_contacts(model, data);
}

}  // namespace elbowsim

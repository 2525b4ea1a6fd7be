#include "engine/contact/pad.hpp"

#include <algorithm>
#include <cmath>

#include "engine/contact/detection.hpp"

namespace elbowsim {

const Pad* slot_pad(const Model& model, const ContactData& c, int slot) {
  const int elbow = c.primitive_of(slot).elbow;
  if (elbow < 0) return nullptr;
  const Pad& pad = model.elbows[static_cast<std::size_t>(elbow)].pad;
  return pad.on() ? &pad : nullptr;
}

void prescribe_pad_rows(const Model& model, ContactData& c) {
  if (!model.has_pads()) return;
  for (int r = 0; r < c.normal_rows(); ++r) {
    if (!slot_pad(model, c, c.active[static_cast<std::size_t>(r)])) continue;
    // The row's own scale (1 / effective mass); a row that cannot move the
    // arm (A_rr 0) still prescribes its force, at unit scale.
    const double scale = c.A(r, r) > 0 ? c.A(r, r) : 1.0;
    c.A.row(r).setZero();
    c.A(r, r) = scale;
    c.rhs[r] = scale * c.gamma[r];
  }
}

double pad_elastic_energy(const Model& model, const ContactData& c) {
  double energy = 0;
  for (int r = 0; r < c.normal_rows(); ++r)
    if (const Pad* pad = slot_pad(model, c, c.active[static_cast<std::size_t>(r)]))
      energy += 0.5 * pad->stiffness * c.C[r] * c.C[r];
  return energy;
}

double pad_loss_rate(const Model& model, const ContactData& c) {
  double rate = 0;
  for (int r = 0; r < c.normal_rows(); ++r)
    if (const Pad* pad = slot_pad(model, c, c.active[static_cast<std::size_t>(r)]))
      rate += pad->damping * c.Cd[r] * c.Cd[r];
  return rate;
}

double pad_power(const Model& model, const ContactData& c) {
  double power = 0;
  for (int r = 0; r < c.normal_rows(); ++r)
    if (slot_pad(model, c, c.active[static_cast<std::size_t>(r)])) power += c.fn[r] * c.Cd[r];
  return power;
}

namespace {

// s(t) of a pad released d0 deep at t0 (time constant c / k; without
// damping it lets go at d0 = 0 and is back at once).
double relaxed_depth(const Pad& pad, double d0, double t0, double t) {
  if (d0 <= 0 || pad.damping <= 0) return 0.0;
  return d0 * std::exp(-pad.stiffness / pad.damping * std::max(0.0, t - t0));
}

}  // namespace

double pad_surface_depth(const Model& model, const ContactData& c, int slot, double t) {
  const Pad* pad = slot_pad(model, c, slot);
  if (!pad || c.resting[slot]) return 0.0;
  const auto k = static_cast<std::size_t>(slot);
  return relaxed_depth(*pad, c.pad_release_depth[k], c.pad_release_time[k], t);
}

double pad_gap(const Model& model, const ContactData& c, int slot, double t) {
  return c.detected[slot].distance + pad_surface_depth(model, c, slot, t);
}

void book_pad_release(const Model& model, Data& data, int slot) {
  ContactData& c = data.contact;
  if (!slot_pad(model, c, slot)) return;
  c.pad_release_depth[static_cast<std::size_t>(slot)] = std::max(0.0, -c.detected[slot].distance);
  c.pad_release_time[static_cast<std::size_t>(slot)] = data.t;
}

void pad_contact_begins(const Model& model, Data& data, int slot) {
  ContactData& c = data.contact;
  const Pad* pad = slot_pad(model, c, slot);
  double& d0 = c.pad_release_depth[static_cast<std::size_t>(slot)];
  if (!pad || d0 <= 0) return;
  const double s = relaxed_depth(*pad, d0, c.pad_release_time[static_cast<std::size_t>(slot)], data.t);
  c.pad_relaxed += 0.5 * pad->stiffness * (d0 * d0 - s * s);
  d0 = 0;
}

bool pad_presses(const Model& model, const Data& data, int slot) {
  const Pad* pad = slot_pad(model, data.contact, slot);
  return pad && pad_gap(model, data.contact, slot, data.t) <= 0 &&
         pad_force(*pad, data.contact.detected[slot].distance, normal_speed(model, data, slot)) > 0;
}

double relaxing_pad_energy(const Model& model, const ContactData& c, double t) {
  double energy = 0;
  for (int k = 0; k < c.slots(); ++k)
    if (const Pad* pad = slot_pad(model, c, k)) {
      const double s = pad_surface_depth(model, c, k, t);
      energy += 0.5 * pad->stiffness * s * s;
    }
  return energy;
}

double pad_relaxation_loss(const Model& model, const ContactData& c, double t) {
  double loss = c.pad_relaxed;
  for (int k = 0; k < c.slots(); ++k) {
    const Pad* pad = slot_pad(model, c, k);
    const double d0 = c.pad_release_depth[static_cast<std::size_t>(k)];
    if (!pad || d0 <= 0 || c.resting[k]) continue;
    const double s = pad_surface_depth(model, c, k, t);
    loss += 0.5 * pad->stiffness * (d0 * d0 - s * s);
  }
  return loss;
}

}  // namespace elbowsim

// Compliant pads on elbows (model.hpp, Pad; docs/model.md, Compliant pad).
//
// A padded elbow that rests keeps its normal row of M*, but the row's force is
// prescribed instead of solved for: f = k d + c d' with d = -C its depth in
// the pad and d' = -Cd. In the Delassus system A f = rhs that row becomes
// f_r = f_pad (scaled by A_rr, so the pivots keep their size); the other rows
// feel it through their columns, and its tangent rows (a sticking pad) stay
// bounded by mu f_pad. The same row in the active set's LCP, w_r = A_rr
// (f_r - f_pad), has the one complementary answer f_r = max(f_pad, 0): a pad
// that would pull is released. The matrix stays a P-matrix when it was one
// (a principal minor with row r is A_rr times the one without).
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// Slot k's pad, or nullptr when it has none (a link's solid, a rigid elbow).
const Pad* slot_pad(const Model& model, const ContactData& c, int slot);

// [N] The pad's push at depth -C [m] and rate -Cd [m/s]; negative where it
// would pull (the release event's function).
inline double pad_force(const Pad& pad, double C, double Cd) {
  return -pad.stiffness * C - pad.damping * Cd;
}

// Rows of padded slots in A [p x p] and rhs [p]: each becomes A_rr f_r =
// A_rr gamma_r (constraint_rows leaves the pad's force in gamma_r). No-op
// without pads.
void prescribe_pad_rows(const Model& model, ContactData& c);

// Over the normal rows of the last constraint_rows: the pads' elastic energy
// sum k C^2 / 2 [J] and their damping loss rate sum c Cd^2 [W].
double pad_elastic_energy(const Model& model, const ContactData& c);
double pad_loss_rate(const Model& model, const ContactData& c);
// The pads' power on the arm [W]: sum f_r Cd_r over their rows.
double pad_power(const Model& model, const ContactData& c);

// A pad that lets go is still pressed d0 = c v / k (where k d + c d' = 0).
// Massless, its surface then comes back up on its own, k s + c s' = 0:
// s(t) = d0 e^(-(k/c)(t - t0)), losing c s'^2 on the way, and the elbow meets
// it again where its distance is -s(t), not 0. book_pad_release marks the
// release at the state in data.x (its detection current); pad_contact_begins
// closes it when the pad is pressed again (its relaxation so far is lost).
void book_pad_release(const Model& model, Data& data, int slot);
void pad_contact_begins(const Model& model, Data& data, int slot);

// [m] s(t) of slot k's pad surface (0: relaxed, pressed, or no pad).
double pad_surface_depth(const Model& model, const ContactData& c, int slot, double t);

// [m] Slot k's distance from what it lands on at its last detection: its
// pad's surface, distance + s(t); the table's, distance, without a pad.
double pad_gap(const Model& model, const ContactData& c, int slot, double t);

// Whether free slot k's pad, at its last detection and the rates in data.x,
// meets the elbow (pad_gap <= 0) and pushes it (k d + c d' > 0): the elbow
// moves into it, or its surface, coming back up, catches the elbow.
bool pad_presses(const Model& model, const Data& data, int slot);

// At time t: the elastic energy still in released pads, sum k s^2 / 2 [J],
// and what the pads lost relaxing so far [J] (the closed relaxations and the
// open ones' k (d0^2 - s^2) / 2).
double relaxing_pad_energy(const Model& model, const ContactData& c, double t);
double pad_relaxation_loss(const Model& model, const ContactData& c, double t);

}  // namespace elbowsim

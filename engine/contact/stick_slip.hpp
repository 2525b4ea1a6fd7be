// Coulomb friction with stick and slip (contact.friction.law: coulomb): which
// resting slot sticks and which slips, decided with the normal forces.
//
// A resting slot sticks (tangent rows hold its contact point; its force f_t
// stays inside the cone |f_t| <= mu f_n) or slips (its normal row carries
// -mu f_n along the slip). Modes change at events located inside a step
// (run/contact_events.hpp): a sticking slot's force reaching the cone's edge starts a
// slip, a slip that stops (its speed along its direction turns negative) may
// stick. When a step starts, the modes carried over are kept if they are
// consistent (forces inside their cones, normal forces >= 0, a slip just
// begun accelerating along its direction); otherwise Stewart and Trinkle's
// LCP (friction_lcp.hpp) decides them with the normal rows.
#pragma once

#include "engine/data.hpp"

namespace elbowsim {

// For the candidates of select_active_set (data.contact.candidates, the
// mechanics of the step's start prepared): sets data.contact.lcp_active (row
// on or off per candidate) and the modes (sticking, slip) of the candidates
// that stay on, logging stick and slip events of slots that rested before.
// Returns false with data.failure set when no consistent set exists.
bool decide_stick_slip(const Model& model, Data& data);

// The rows of the step from the modes: a normal row for every slot in
// data.contact.active, then tangent rows for the sticking ones.
void tangent_rows_from_modes(const Model& model, Data& data);

// At the last rows solve (constraint_rows and the forces in data.contact.fn):
// slot k's friction force [N, world] on the arm, and mu f_n - |f_t| [N] of a
// sticking slot (< 0: outside the cone, the slip begins).
Eigen::Vector3d friction_force(const Model& model, const Data& data, int slot);
double cone_margin(const Model& model, const Data& data, int slot);

// A sliding slot's speed along its slip direction [m/s] at the rates of
// data.x (< 0: the slip stopped and turned). Needs forward_kinematics.
double slip_speed(const Model& model, const Data& data, int slot);

}  // namespace elbowsim

// Impacts: a landing slot with approach speed gets an impulse. All slots
// that land together, and those already resting, are solved jointly:
//   u+ = u- + A P,  A = Jc (M + Jm)^-1 Jc^T,  P >= 0,
//   w = u+ + e u-(landing rows) >= 0,  P . w = 0     (Newton restitution e)
// and qd+ = qd- + (M + Jm)^-1 Jc^T P. With Coulomb friction (law coulomb)
// each contact also gets a tangential impulse inside its cone, |P_t| <= mu P_n,
// that stops its contact point's slip if the cone allows, else slides it with
// |P_t| = mu P_n (friction_lcp.hpp at the velocity level; Jc then holds the
// tangent rows too). The regularised laws have no impulsive friction.
#pragma once

#include <vector>

#include "engine/data.hpp"

namespace elbowsim {

// Per contact (landing slots first, then resting ones): views into the run's
// contact workspace, valid until the next impact. Unsolved: empty views.
struct ImpactResult {
  ConstVec impulse;        // [N s]
  ConstVec speed_before;   // [m/s] normal velocity (< 0 approaching)
  ConstVec speed_after;    // [m/s]
  ConstVec energy_lost;    // [J] -P_k (u-_k + u+_k) / 2 over the contact's rows; they sum to the loss
  double kinetic_before = 0, kinetic_after = 0;  // [J] 1/2 qd^T (M + Jm) qd
  bool solved = false;
};

// Applies the impulse to the rates in data.x for the slots `landing` (with
// Newton restitution `restitution`) and `resting`. Needs forward_kinematics at
// the state's q and the detection of every slot involved. Allocates nothing
// (at most contact capacity rows; more is unsolved). With Coulomb friction it
// sets the modes of the slots involved.
ImpactResult apply_impact(const Model& model, Data& data, const std::vector<int>& landing,
                          const std::vector<int>& resting, double restitution);

// [m/s] The rebound speed below which a landing settles (contact.settle_speed,
// by default |gravity| x step: a ball rebounding slower is back within two
// steps and rises at most g h^2 / 2, 4.9 um at 1 ms). 0 without gravity.
double settle_speed(const Model& model);

// The impact stage of a step: every free slot at or into the table
// (distance <= 0, or <= touch_distance with located events) and approaching
// faster than contact.separation_velocity lands; with effects.impacts it gets its impulse. Landing events go to
// data.log; the impact loss to data.contact.impact_loss. No solution: data.failure.
// A slot the impulse leaves separating is released at once (a bounce: landing
// and release events at the same instant); if a landing slot would rebound
// slower than settle_speed the impact is redone plastic (restitution 0) and
// the slot rests: the Zeno series of ever shorter bounces ends there.
void land_touching_slots(const Model& model, Data& data);

}  // namespace elbowsim

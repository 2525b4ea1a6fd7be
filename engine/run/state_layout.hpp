// Layout of the integrated state
//   x = [q; qd; i (motor: full); E_in; E_joule; E_viscous; E_friction, E_normal (contact);
//        E_drawn, E_regenerated (motors); E_joint_friction (joint friction); E_gear (gear losses);
//        E_external (hand force)].
// The energy integrals ride along in x so they are integrated to the same
// order as the motion they account for.
#pragma once

#include "engine/model.hpp"

namespace elbowsim {

struct StateLayout {
  // Each optional block takes the next indices, in the order above.
  explicit StateLayout(const Model& model)
      : n(model.dof), current(model.has_current_state() ? 2 * n : -1),
        energy(model.has_current_state() ? 3 * n : 2 * n) {
    int next = energy + (model.effects.contact ? 5 : 3);
    auto take = [&next](bool present, int count) { return present ? (next += count) - count : -1; };
    drawn = take(model.has_motor(), 2);
    joint_friction = take(model.effects.joint_friction, 1);
    gear = take(model.gear_losses, 1);
    external = take(!model.hand_load.force.isZero(), 1);
    size = next;
    energy_terms = size - energy;
  }
  int n;
  int q() const { return 0; }
  int qd() const { return n; }
  int current;  // first current index, -1 without current state
  int energy;   // index of E_in; E_joule, E_viscous (and E_friction, E_normal) follow
  int drawn;           // index of E_drawn (E_regenerated follows), -1 without motors
  int joint_friction;  // index of E_joint_friction, -1 without joint friction
  int gear;            // index of E_gear, -1 with lossless gears
  int external;        // index of the hand-force work integral, -1 without a hand force
  int size;
  int energy_terms;    // size - energy
};

}  // namespace elbowsim

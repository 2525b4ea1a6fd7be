// Layout of the integrated state
//   x = [q; qd; i (motor: full); E_in; E_joule; E_viscous; E_friction, E_normal (contact);
//        E_drawn, E_regenerated (motors); E_joint_friction (joint friction); E_gear (gear losses);
//        E_external (hand force); E_friction per contact body (contact with friction:
//        each elbow, then each link)].
// The energy integrals ride along in x so they are integrated to the same
// order as the motion they account for. The per-body friction integrals come
// last and the adaptive error control leaves them out (`controlled`): they
// split E_friction by body and must not change the steps the run takes.
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
    const int bodies = static_cast<int>(model.elbows.size()) + n;
    body_friction = take(model.effects.contact && model.effects.friction, bodies);
    size = next;
    controlled = body_friction >= 0 ? body_friction : size;
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
  int body_friction;   // index of elbow 0's friction loss (then each elbow's, each link's), or -1
  int size;
  int controlled;      // the first `controlled` components are weighed by adaptive error control
  int energy_terms;    // size - energy
};

}  // namespace elbowsim

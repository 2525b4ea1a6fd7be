// Layout of the integrated state
//   x = [q; qd; i (motor: full); E_in; E_joule; E_viscous; E_friction, E_normal (contact)].
// The energy integrals ride along in x so they are integrated to the same
// order as the motion they account for.
#pragma once

#include "model.hpp"

namespace elbowsim {

struct StateLayout {
  explicit StateLayout(const Model& model)
      : n(model.dof), current(model.has_current_state() ? 2 * n : -1),
        energy(model.has_current_state() ? 3 * n : 2 * n),
        energy_terms(model.effects.contact ? 5 : 3), size(energy + energy_terms) {}
  int n;
  int q() const { return 0; }
  int qd() const { return n; }
  int current;  // first current index, -1 without current state
  int energy;   // index of E_in; E_joule, E_viscous (and E_friction, E_normal) follow
  int energy_terms;
  int size;
};

}  // namespace elbowsim

// Layout of the integrated state x = [q; qd; i (motor: full); E_in; E_joule; E_viscous].
// The energy integrals ride along in x so they are integrated to the same
// order as the motion they account for.
#pragma once

#include "model.hpp"

namespace elbowsim {

struct StateLayout {
  explicit StateLayout(const Model& model)
      : n(model.dof), current(model.has_current_state() ? 2 * n : -1),
        energy(model.has_current_state() ? 3 * n : 2 * n), size(energy + 3) {}
  int n;
  int q() const { return 0; }
  int qd() const { return n; }
  int current;  // first current index, -1 without current state
  int energy;   // index of E_in; E_joule and E_viscous follow
  int size;
};

}  // namespace elbowsim

// Layout of the integrated state
//   x = [q; qd; i (motor: full); the integrated energy terms present, in the
//        order of engine/recording/energy_terms.hpp (E_in, E_joule, E_viscous; E_friction,
//        E_normal (contact); E_drawn, E_regenerated (motors); E_joint_friction;
//        E_gear; E_external (hand force); E_pad (pads)); E_friction per contact body (contact
//        with friction: each elbow, then each link)].
// The energy integrals ride along in x so they are integrated to the same
// order as the motion they account for. The per-body friction integrals come
// last and the adaptive error control leaves them out (`controlled`): they
// split E_friction by body and must not change the steps the run takes.
#pragma once

#include <array>

#include "engine/recording/energy_terms.hpp"
#include "engine/model.hpp"

namespace elbowsim {

// Whether the model has the terms of `group` (energy_terms.hpp).
inline bool energy_group_present(const Model& model, EnergyGroup group) {
  switch (group) {
    case EnergyGroup::always: return true;
    case EnergyGroup::contact: return model.effects.contact;
    case EnergyGroup::motors: return model.has_motor();
    case EnergyGroup::joint_friction: return model.effects.joint_friction;
    case EnergyGroup::gear: return model.gear_losses;
    case EnergyGroup::hand_force: return !model.hand_load.force.isZero();
    case EnergyGroup::pads: return model.has_pads();
    case EnergyGroup::springs: return model.has_springs();
  }
  return false;
}

struct StateLayout {
  // Each present block takes the next indices, in the order above.
  explicit StateLayout(const Model& model)
      : n(model.dof), current(model.has_current_state() ? 2 * n : -1),
        energy(model.has_current_state() ? 3 * n : 2 * n) {
    int next = energy;
    for (const EnergyTermInfo& t : kEnergyTerms)
      slots_[static_cast<std::size_t>(t.term)] =
          t.source == EnergySource::integrated && energy_group_present(model, t.group) ? next++
                                                                                       : -1;
    const int bodies = static_cast<int>(model.elbows.size()) + n;
    body_friction = model.effects.contact && model.effects.friction ? next : -1;
    if (body_friction >= 0) next += bodies;
    size = next;
    controlled = body_friction >= 0 ? body_friction : size;
    energy_terms = size - energy;
  }
  int n;
  int q() const { return 0; }
  int qd() const { return n; }
  int current;  // first current index, -1 without current state
  int energy;   // index of E_in, the first energy integral
  // The slot of an integrated energy term, -1 when the model has none.
  int slot(Energy e) const { return slots_[static_cast<std::size_t>(e)]; }
  int body_friction;   // index of elbow 0's friction loss (then each elbow's, each link's), or -1
  int size;
  int controlled;      // the first `controlled` components are weighed by adaptive error control
  int energy_terms;    // size - energy

 private:
  std::array<int, kEnergyTermCount> slots_;
};

}  // namespace elbowsim
